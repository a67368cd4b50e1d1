"""Time the VTK output process on the 2D Hertz example (issue 18 item 5).

Runs the first load step of ``examples/hertz_2d`` at a refinement level in a temporary folder,
then writes its VTK output ``--repeat`` times through the bulk arrays of ``_core`` and through the
per-entity Python path (the one before issue 18, kept for extrapolated Gauss-point variables), and
prints the mean seconds per output of each (with ``--profile``, the cProfile lines of one bulk
output). ``--refinement 4`` has 94k nodes (188k DoFs);
level 3 has 23k nodes.

    python benchmarks/vtk_output_benchmark.py --refinement 4 [--repeat 3] [--profile]
"""

from __future__ import annotations

import argparse
import cProfile
import json
import pstats
import sys
import tempfile
import time
from pathlib import Path

import contact_app as ca

EXAMPLE = Path(__file__).resolve().parent.parent / "examples" / "hertz_2d"
sys.path[:0] = [str(EXAMPLE), str(EXAMPLE.parent)]
import make_mesh  # noqa: E402  (examples/hertz_2d/make_mesh.py)
from hertz_common import working_directory  # noqa: E402


def main(argv: list[str] | None = None) -> int:
    """Print the seconds per VTK output of the first step of hertz_2d."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--refinement", type=int, default=3)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--profile", action="store_true", help="cProfile one output")
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as folder, working_directory(Path(folder)):
        make_mesh.write_mesh(Path(folder) / "hertz_2d.msh", args.refinement)
        parameters = json.loads((EXAMPLE / "ProjectParameters.json").read_text())
        parameters["problem_data"]["end_time"] = parameters["solver_settings"]["time_stepping"][
            "time_step"
        ]
        materials = parameters["solver_settings"]["material_import_settings"]
        materials["materials_filename"] = str(EXAMPLE / "materials.json")
        analysis = ca.analysis.run(parameters, quiet=True, stop_on_non_convergence=False)
        part = analysis.model.GetModelPart("Structure")
        (vtk,) = [
            p
            for p in analysis._GetListOfOutputProcesses()
            if type(p).__name__ == "VtkOutputProcess"
        ]
        dofs = 2 * part.NumberOfNodes() + part.GetSubModelPart("Contact_Slave").NumberOfNodes()
        timings = {}
        for path in ("per-entity", "bulk"):
            if path == "per-entity":
                vtk._gather_bulk = vtk._gather_per_entity
            else:
                del vtk._gather_bulk
            start = time.perf_counter()
            for _ in range(args.repeat):
                vtk.PrintOutput()
            timings[path] = (time.perf_counter() - start) / args.repeat
        print(
            f"hertz_2d refinement {args.refinement}: {part.NumberOfNodes()} nodes, "
            f"{part.NumberOfElements()} elements, about {dofs} DoFs; seconds per VTK output "
            f"(mean of {args.repeat}): per-entity {timings['per-entity']:.3f}, "
            f"bulk {timings['bulk']:.3f}"
        )
        if args.profile:
            profiler = cProfile.Profile()
            profiler.runcall(vtk.PrintOutput)
            pstats.Stats(profiler).sort_stats("cumulative").print_stats(25)
    return 0


if __name__ == "__main__":
    sys.exit(main())
