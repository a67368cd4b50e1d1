"""Reference numbers of the frictional patch-test variants, computed by the Kratos oracle.

The reference suite runs the 2D hyper-simple frictional patch (two quads, one contact pair) in
several variants (slip, stick, threshold slip, no friction, perfect stick; ALM and penalty) whose
input files are not in ../shared/kratos_cases. Each variant is rebuilt in
``tests/python/contact/data/kratos_oracle/cases/<name>/`` (``parameters.json`` + ``materials.json``;
the mesh stays in ../shared/kratos_cases, every path is relative to the case folder, and the
``_reconstruction`` key says where each setting comes from). This script runs every case folder with
the installed Kratos and writes ``kratos_oracle/<name>.json``: the final DISPLACEMENT of the
Contact_Part nodes plus, per slave node, the contact state the friction code must reproduce
(ACTIVE, SLIP, augmented pressures, WEIGHTED_SLIP), and the summed REACTION of the fixed nodes;
for a case of several steps, the slave nodes' state after every step (``history``).
The general ALM case and the penalty perfect stick are in ../shared/kratos_cases already: their
fixtures (``alm_frictional_2d_hyper_simple``, ``penalty_frictional_2d_stick``) come from
generate_kratos_fixtures.py, hence ``*_stick_ramp`` for the press-then-slide stick variants.
The suite's static-evolution and dynamic evolution-load variants come without meshes: their folders
(``alm_frictional_2d_static_evolution_load``, ``alm_frictional_2d_evolution_load``) run our own
model of the same character, ``cases/frictional_evolution_load_2d.mdpa`` written by
make_evolution_load_mesh.py.

Usage (same separate virtual environment as generate_kratos_fixtures.py)::

    /tmp/kratos_venv/bin/python scripts/oracle/generate_friction_fixtures.py [name ...]
"""

from __future__ import annotations

import importlib.metadata
import json
import os
import sys
from pathlib import Path

import KratosMultiphysics as KM  # the oracle, only in its own environment
import KratosMultiphysics.ContactStructuralMechanicsApplication as CSMA
import KratosMultiphysics.StructuralMechanicsApplication  # noqa: F401
from KratosMultiphysics.StructuralMechanicsApplication.structural_mechanics_analysis import (
    StructuralMechanicsAnalysis,
)

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "tests" / "python" / "contact" / "data" / "kratos_oracle"
CASES_DIR = OUT / "cases"


def _components(node, variable_name: str, historical: bool) -> dict[str, float]:
    """The x and y components of a nodal vector (the patch is 2D)."""
    variable = KM.KratosGlobals.GetVariable(variable_name)
    value = node.GetSolutionStepValue(variable) if historical else node.GetValue(variable)
    return {f"{variable_name}_X": float(value[0]), f"{variable_name}_Y": float(value[1])}


def _reaction_sums(main, raw: dict) -> dict:
    """REACTION summed over each constrained sub model part and over all their nodes.

    Read from the constraint processes' model parts: the fixities are released after the last step.
    """
    by_part: dict[str, dict] = {}
    ids: set[int] = set()
    for process in raw["processes"]["constraints_process_list"]:
        name = process["Parameters"]["model_part_name"]
        nodes = list(main.GetSubModelPart(name.removeprefix("Structure.")).Nodes)
        ids.update(n.Id for n in nodes)
        by_part[name] = {
            "nodes": sorted(n.Id for n in nodes),
            "REACTION_X": sum(n.GetSolutionStepValue(KM.REACTION_X) for n in nodes),
            "REACTION_Y": sum(n.GetSolutionStepValue(KM.REACTION_Y) for n in nodes),
        }
    fixed = [main.GetNode(i) for i in sorted(ids)]
    return {
        "nodes": sorted(ids),
        "REACTION_X": sum(n.GetSolutionStepValue(KM.REACTION_X) for n in fixed),
        "REACTION_Y": sum(n.GetSolutionStepValue(KM.REACTION_Y) for n in fixed),
        "by_part": by_part,
    }


def _contact_state(main) -> tuple[dict, dict]:
    """DISPLACEMENT of the Contact_Part nodes; contact state and ACTIVE/SLIP of its slave nodes."""
    values: dict[str, dict[str, float]] = {}
    flags: dict[str, dict[str, bool]] = {}
    for node in main.GetSubModelPart("Contact_Part").Nodes:
        entry = values.setdefault(f"NODE_{node.Id}", {})
        entry["DISPLACEMENT_X"] = node.GetSolutionStepValue(KM.DISPLACEMENT_X)
        entry["DISPLACEMENT_Y"] = node.GetSolutionStepValue(KM.DISPLACEMENT_Y)
        if not node.Is(KM.SLAVE):
            continue
        entry["AUGMENTED_NORMAL_CONTACT_PRESSURE"] = node.GetValue(
            CSMA.AUGMENTED_NORMAL_CONTACT_PRESSURE
        )
        entry.update(_components(node, "AUGMENTED_TANGENT_CONTACT_PRESSURE", historical=False))
        entry.update(_components(node, "WEIGHTED_SLIP", historical=True))
        flags[f"NODE_{node.Id}"] = {"ACTIVE": node.Is(KM.ACTIVE), "SLIP": node.Is(KM.SLIP)}
    return values, flags


#: What ``history`` keeps per step, per slave node (arrays in the order of ``nodes``).
HISTORY_VALUES = (
    "DISPLACEMENT_X",
    "DISPLACEMENT_Y",
    "AUGMENTED_NORMAL_CONTACT_PRESSURE",
    "AUGMENTED_TANGENT_CONTACT_PRESSURE_X",
    "AUGMENTED_TANGENT_CONTACT_PRESSURE_Y",
    "WEIGHTED_SLIP_X",
    "WEIGHTED_SLIP_Y",
)


class _RecordingAnalysis(StructuralMechanicsAnalysis):
    """The analysis, keeping the slave nodes' state and the reactions after every step."""

    def __init__(self, model, parameters, raw: dict) -> None:
        super().__init__(model, parameters)
        self.raw = raw
        self.history: list[dict] = []

    def FinalizeSolutionStep(self) -> None:  # noqa: N802 - Kratos name
        super().FinalizeSolutionStep()
        main = self.model.GetModelPart("Structure")
        values, flags = _contact_state(main)
        nodes = sorted(flags, key=lambda key: int(key.removeprefix("NODE_")))
        reactions = _reaction_sums(main, self.raw)
        self.history.append(
            {
                "time": main.ProcessInfo[KM.TIME],
                "iterations": main.ProcessInfo[KM.NL_ITERATION_NUMBER],
                "nodes": [int(key.removeprefix("NODE_")) for key in nodes],
                **{name: [values[key][name] for key in nodes] for name in HISTORY_VALUES},
                **{flag: [flags[key][flag] for key in nodes] for flag in ("ACTIVE", "SLIP")},
                **{name: reactions[name] for name in ("REACTION_X", "REACTION_Y")},
            }
        )


def run(name: str) -> dict:
    """Run the case folder ``name`` (Kratos reads its paths relative to the folder).

    A case of more than one step also gets ``history``: per step the slave nodes' displacements,
    augmented pressures, WEIGHTED_SLIP and ACTIVE/SLIP, the Newton iterations and the summed
    reactions.
    """
    folder = CASES_DIR / name
    os.chdir(folder)
    raw = json.loads((folder / "parameters.json").read_text())
    model = KM.Model()
    analysis = _RecordingAnalysis(model, KM.Parameters(json.dumps(raw)), raw)
    analysis.Run()
    main = model.GetModelPart("Structure")
    values, flags = _contact_state(main)
    result = {
        "case": f"cases/{name}",
        "components": False,
        "kratos": importlib.metadata.version("KratosMultiphysics"),
        "time": main.ProcessInfo[KM.TIME],
        "steps": main.ProcessInfo[KM.STEP],
        "values": values,
        "flags": flags,
        "reaction_sum": _reaction_sums(main, raw),
    }
    if len(analysis.history) > 1:
        result["history"] = analysis.history
    return result


def main() -> int:
    """Regenerate the fixtures of the named case folders, all by default."""
    selected = sys.argv[1:] or sorted(p.name for p in CASES_DIR.iterdir() if p.is_dir())
    for name in selected:
        target = OUT / f"{name}.json"
        if target.exists() and not json.loads(target.read_text())["case"].startswith("cases/"):
            print(f"{name}: {target.name} belongs to generate_kratos_fixtures.py", file=sys.stderr)
            continue
        try:
            result = run(name)
        except Exception as failure:  # report and go on with the other cases
            print(f"{name}: Kratos failed: {failure}", file=sys.stderr)
            continue
        target.write_text(json.dumps(result, indent=1, sort_keys=True) + "\n")
        print(f"{name}: t = {result['time']:.6g}, slave state {result['flags']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
