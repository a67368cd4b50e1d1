"""The cattaneo_mindlin_3d example (frictional ALM, 3D) at its coarsest level, for the thread test.

``python parallel_assembly_case.py DIRECTORY``: writes the mesh into DIRECTORY, runs the example
without output with the thread count of the environment (OMP_NUM_THREADS) and writes
``result.npz`` there: the Newton iterations per step, DISPLACEMENT and REACTION of every node and
VECTOR_LAGRANGE_MULTIPLIER, ACTIVE and SLIP of the slave nodes, by node id.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
from example_runs import load_make_mesh, run_without_output  # same folder

import contact_app as ca

EXAMPLE = Path(__file__).resolve().parents[3] / "examples" / "cattaneo_mindlin_3d"


def main(argv: list[str]) -> int:
    """Run the case in the directory ``argv[0]`` and write its result there."""
    directory = Path(argv[0])
    mesh = directory / "cattaneo_mindlin_3d.msh"
    load_make_mesh(EXAMPLE).write_mesh(mesh, 1)
    parameters = json.loads((EXAMPLE / "ProjectParameters.json").read_text())
    solver = parameters["solver_settings"]
    solver["model_import_settings"]["input_filename"] = str(mesh)
    solver["material_import_settings"]["materials_filename"] = str(EXAMPLE / "materials.json")
    analysis, _ = run_without_output(parameters)
    main_part = analysis.model.GetModelPart("Structure")
    nodes = sorted(main_part.Nodes, key=lambda node: node.Id)
    slave = sorted(main_part.GetSubModelPart("Contact_Slave").Nodes, key=lambda node: node.Id)
    np.savez(
        directory / "result.npz",
        iterations=np.array([step.iterations for step in analysis.reporter.steps]),
        converged=np.array([step.converged for step in analysis.reporter.steps]),
        displacement=np.array([node.GetSolutionStepValue(ca.DISPLACEMENT) for node in nodes]),
        reaction=np.array([node.GetSolutionStepValue(ca.REACTION) for node in nodes]),
        multiplier=np.array(
            [node.GetSolutionStepValue(ca.VECTOR_LAGRANGE_MULTIPLIER) for node in slave]
        ),
        active=np.array([node.Is(ca.ACTIVE) for node in slave]),
        slip=np.array([node.Is(ca.SLIP) for node in slave]),
    )
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
