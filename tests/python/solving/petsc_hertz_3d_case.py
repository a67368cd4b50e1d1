"""The hertz_3d example at its coarsest level, for the PETSc tests (also run under mpirun).

``python petsc_hertz_3d_case.py DIRECTORY SOLVER_TYPE [MORTAR_TYPE [LINEAR_JSON]]``: writes the
mesh into DIRECTORY, runs the example without output with ``linear_solver_settings.solver_type`` =
SOLVER_TYPE (tolerance 1e-10 for the Krylov solver; MORTAR_TYPE "" = the example's; LINEAR_JSON:
more linear_solver_settings keys) and, on MPI rank 0, writes ``result.json``
there: the Newton iterations per step, the displacements by node id, the linear solver's figures
and the number of MPI ranks. Every rank runs the whole analysis (the same assembly); the PETSc
solver distributes rank 0's system over the ranks and gives every rank the solution
(docs/running.md, "Iterative solver (PETSc)").
"""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any

from example_runs import load_make_mesh, run_without_output  # same folder

import contact_app as ca

HERTZ_3D = Path(__file__).resolve().parents[3] / "examples" / "hertz_3d"


def run(
    directory: Path,
    solver_type: str,
    mortar_type: str | None = None,
    linear: dict[str, Any] | None = None,
) -> tuple[Any, str]:
    """Run the case in ``directory``; return the analysis and its printed table.

    ``linear``: more linear_solver_settings keys.
    """
    mesh = directory / "hertz_3d.msh"
    if not mesh.exists():
        load_make_mesh(HERTZ_3D).write_mesh(mesh, 1)
    parameters = json.loads((HERTZ_3D / "ProjectParameters.json").read_text())
    solver = parameters["solver_settings"]
    solver["model_import_settings"]["input_filename"] = str(mesh)
    solver["material_import_settings"]["materials_filename"] = str(HERTZ_3D / "materials.json")
    solver["linear_solver_settings"] = {"solver_type": solver_type}
    if ca.ResolveLinearSolverName(solver_type) == "petsc":
        solver["linear_solver_settings"]["tolerance"] = 1.0e-10
    solver["linear_solver_settings"].update(linear or {})
    if mortar_type:
        solver["contact_settings"]["mortar_type"] = mortar_type
    return run_without_output(parameters)


def displacements(analysis: Any) -> dict[int, list[float]]:
    """DISPLACEMENT by node id."""
    main = analysis.model.GetModelPart("Structure")
    return {
        int(node.Id): [float(v) for v in node.GetSolutionStepValue(ca.DISPLACEMENT)]
        for node in main.Nodes
    }


def main(argv: list[str]) -> int:
    directory, solver_type = Path(argv[0]), argv[1]
    mortar_type = argv[2] if len(argv) > 2 else None
    linear = json.loads(argv[3]) if len(argv) > 3 else None
    analysis, table = run(directory, solver_type, mortar_type, linear)
    statistics = dict(analysis.reporter.linear_solver or {})
    rank, ranks = ca.MpiRankAndSize() if statistics.get("krylov") else (0, 1)
    if rank == 0:
        result = {
            "ranks": ranks,
            "iterations": [step.iterations for step in analysis.reporter.steps],
            "krylov": [step.krylov for step in analysis.reporter.steps],
            "displacements": displacements(analysis),
            "statistics": {k: v for k, v in statistics.items() if isinstance(v, (int, float, str))},
            "table": table,
        }
        (directory / "result.json").write_text(json.dumps(result))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
