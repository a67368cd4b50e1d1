"""Contact faces given with an inward normal are flipped at set-up, named, and solve alike.

Issue 16: reversing the node order of the contact conditions of an interface must not change the
answer. A block pressed on a base (test_initial_penetration's case, touching start), with the two
contact faces written as explicit LineCondition2D2N / SurfaceCondition3D4N / SurfaceCondition3D3N
conditions of the .mdpa, is run once correctly oriented and once with the node order of the slave,
of the master, of both or of every other slave face reversed. NormalCheckProcess flips the inverted
faces; the contact process warns, naming the model part and the ids of the flipped conditions. The
run converges in as many iterations and its displacements, reactions, multipliers, weighted gaps,
nodal normals and active set equal the oriented run's to round-off (1e-10 relative).

Before the fix the flipped faces kept the MARKER that NormalCheckProcess sets; the search takes a
MARKER face for one owned by another search and worked on a clone with a new id, leaving each
flipped face twice in the Contact part (the answer was unchanged here, the Contact part was not).
"""

from __future__ import annotations

import logging
from pathlib import Path

import numpy as np
import pytest
from patch_meshes import Mdpa, box, faces_on, quad_block
from test_initial_penetration import write_case

import contact_app as ca
from contact_app.analysis import StructuralMechanicsAnalysis
from contact_app.analysis.reporting import Reporter
from contact_app.parameters import Parameters

#: Faces whose node order is reversed: none, every slave face, every master face, both, or the
#: slave faces at even positions only.
FLIPS = ("none", "slave", "master", "both", "alternate")
#: (dimension, tetrahedra): quadrilaterals, hexahedra, tetrahedra.
MESHES = ((2, False), (3, False), (3, True))


def _reversed(faces: list[list[int]], which: str, side: str) -> list[list[int]]:
    if which in (side, "both"):
        return [face[::-1] for face in faces]
    if which == "alternate" and side == "slave":
        return [face[::-1] if k % 2 == 0 else face for k, face in enumerate(faces)]
    return faces


def write_mesh(directory: Path, dimension: int, tetrahedra: bool, flip: str) -> dict[str, list]:
    """The touching block-on-base case with explicit contact conditions; returns the faces."""
    parameters = write_case(directory, 0.0, dimension)
    mesh = Mdpa()
    if dimension == 2:
        lower = quad_block((0.0, 0.0), (1.0, 0.5), (3, 2), 1, 1)
        upper = quad_block((0.0, 0.5), (1.0, 0.5), (4, 2), 16, 7)
        element, load = "SmallDisplacementElement2D4N", "LineLoadCondition2D2N"
        condition = "LineCondition2D2N"
    else:
        lower = box((0.0, 0.0, 0.0), (1.0, 1.0, 0.5), (3, 3, 2), 1, 1, tetrahedra=tetrahedra)
        first = 1 + len(lower.elements)
        upper = box((0.0, 0.0, 0.5), (1.0, 1.0, 0.5), (4, 4, 2), 49, first, tetrahedra=tetrahedra)
        nodes = 4 if tetrahedra else 8
        element = f"SmallDisplacementElement3D{nodes}N"
        load = f"SurfaceLoadCondition3D{3 if tetrahedra else 4}N"
        condition = f"SurfaceCondition3D{3 if tetrahedra else 4}N"
    axis = dimension - 1
    mesh.add_part("Base", lower.where(axis, 0))
    mesh.add_body("Lower", element, lower, 0)
    mesh.add_body("Upper", element, upper, 0)
    mesh.add_conditions("Top_Load", load, faces_on(upper, axis, -1))
    slave = _reversed(faces_on(upper, axis, 0), flip, "slave")
    master = _reversed(faces_on(lower, axis, -1), flip, "master")
    mesh.add_conditions("Contact_Slave", condition, slave)
    mesh.add_conditions("Contact_Master", condition, master)
    mesh.add_part("Roller_X", lower.where(0, 0) + upper.where(0, 0))
    if dimension == 3:
        mesh.add_part("Roller_Y", lower.where(1, 0) + upper.where(1, 0))
    mesh.write(directory / "case.mdpa")
    assert parameters == directory / "ProjectParameters.json"
    return {"slave": slave, "master": master}


def run(directory: Path, dimension: int, tetrahedra: bool, flip: str) -> dict:
    """Runs one orientation; returns the results to compare and the interface faces."""
    directory.mkdir()
    faces = write_mesh(directory, dimension, tetrahedra, flip)
    reporter = Reporter(quiet=True)
    analysis = StructuralMechanicsAnalysis(
        ca.Model(),
        Parameters((directory / "ProjectParameters.json").read_text()),
        reporter=reporter,
        stop_on_non_convergence=False,
    )
    analysis.Run()
    structure = analysis.model["Structure"]
    nodes = sorted(structure.Nodes, key=lambda n: n.Id)
    slave = sorted(structure.GetSubModelPart("Contact_Slave").Nodes, key=lambda n: n.Id)

    def values(node_list: list, variables: tuple) -> np.ndarray:
        return np.array([[n.GetSolutionStepValue(v) for v in variables] for n in node_list])

    xyz = (ca.DISPLACEMENT_X, ca.DISPLACEMENT_Y, ca.DISPLACEMENT_Z)
    contact = structure.GetSubModelPart("Contact")
    return {
        "displacement": values(nodes, xyz),
        "reaction": values(nodes, (ca.REACTION_X, ca.REACTION_Y, ca.REACTION_Z)),
        "pressure": values(slave, (ca.LAGRANGE_MULTIPLIER_CONTACT_PRESSURE,)),
        "weighted_gap": values(slave, (ca.WEIGHTED_GAP,)),
        "normal": values(slave, (ca.NORMAL_X, ca.NORMAL_Y, ca.NORMAL_Z)),
        "active": [n.Id for n in slave if n.Is(ca.ACTIVE)],
        "steps": [(r.converged, r.iterations) for r in reporter.steps],
        "contact_conditions": sorted(c.Id for c in contact.Conditions),
        "faces": faces,
    }


def _flip_warnings(caplog: pytest.LogCaptureFixture) -> list[str]:
    return [
        r.getMessage()
        for r in caplog.records
        if r.name == "contact_app.contact" and "were flipped" in r.getMessage()
    ]


def _expected_flipped(result: dict, reference: dict, side: str) -> list[int]:
    """Ids of the conditions of ``side`` written in the other order than in the reference.

    The file holds the loaded top faces (as many as the slave faces), the slave, then the master
    faces, numbered from 1.
    """
    count = len(reference["faces"]["slave"])
    first = 1 + count + (count if side == "master" else 0)
    pairs = zip(result["faces"][side], reference["faces"][side], strict=True)
    return [first + k for k, (face, good) in enumerate(pairs) if face != good]


@pytest.mark.parametrize(("dimension", "tetrahedra"), MESHES, ids=("quad", "hexa", "tetra"))
def test_inverted_contact_faces_are_flipped_and_solve_as_the_oriented_ones(
    tmp_path: Path, caplog: pytest.LogCaptureFixture, dimension: int, tetrahedra: bool
) -> None:
    caplog.set_level(logging.WARNING, logger="contact_app")
    results = {}
    for flip in FLIPS:
        caplog.clear()
        results[flip] = run(tmp_path / flip, dimension, tetrahedra, flip)
        results[flip]["warnings"] = _flip_warnings(caplog)
    reference = results["none"]
    assert reference["warnings"] == []
    assert reference["steps"][0][0], "the oriented run must converge"
    assert len(reference["active"]) == len(reference["pressure"]) > 0
    for flip in FLIPS[1:]:
        result = results[flip]
        # (c) converges, in as many iterations as the oriented run.
        assert result["steps"] == reference["steps"], flip
        # (a) one warning naming the model parts and the ids of the flipped conditions.
        assert len(result["warnings"]) == 1, (flip, result["warnings"])
        message = result["warnings"][0]
        total = 0
        for side, part in (("slave", "Contact_Slave"), ("master", "Contact_Master")):
            ids = _expected_flipped(result, reference, side)
            total += len(ids)
            if ids:
                listed = ", ".join(map(str, ids[:20])) + (
                    f", ... ({len(ids) - 20} more)" * (len(ids) > 20)
                )
                assert f"Structure.{part}: {listed}" in message, message
            else:
                assert f"Structure.{part}:" not in message, message
        assert message.startswith(f"alm_contact_process: {total} interface condition(s)")
        # No clone of a flipped face: the Contact part holds the same conditions.
        assert result["contact_conditions"] == reference["contact_conditions"], flip
        # (b) the same answer to round-off.
        assert result["active"] == reference["active"], flip
        for key in ("displacement", "reaction", "pressure", "weighted_gap", "normal"):
            # The bodies touch: the weighted gap is round-off (1e-18) and is measured against
            # the displacements instead.
            scale = np.abs(reference["displacement" if key == "weighted_gap" else key]).max()
            np.testing.assert_allclose(
                result[key], reference[key], rtol=0, atol=1e-10 * scale, err_msg=f"{flip} {key}"
            )
