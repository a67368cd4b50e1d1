"""What the hertz_2d and hertz_3d example tests share: loading, inputs, the script run, the study.

Imported by the tests as ``hertz_examples_common`` (pytest puts this folder on ``sys.path``).
"""

from __future__ import annotations

import importlib.util
import math
import shutil
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from types import ModuleType
from typing import Any

EXAMPLES = Path(__file__).parents[3] / "examples"


def load(example: Path, name: str) -> ModuleType:
    """The script ``example/<name>.py`` as the module ``name`` (reloaded on every call)."""
    spec = importlib.util.spec_from_file_location(name, example / f"{name}.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up there
    spec.loader.exec_module(module)
    return module


def copy_inputs(example: Path, directory: Path) -> None:
    """Copy the example's ProjectParameters.json and materials.json to ``directory``."""
    for name in ("ProjectParameters.json", "materials.json"):
        shutil.copy(example / name, directory / name)


def run_coarsest(example: Path, directory: Path) -> None:
    """Run the example's script on its coarsest mesh in ``directory``, as a user does.

    Checks the exit code, the mesh, the plot (a PNG), the summary (all steps converged, the same
    text as printed) and the four steps of VTK output.
    """
    copy_inputs(example, directory)
    name = example.name
    run = subprocess.run(
        [sys.executable, str(example / f"run_{name}.py"), "--refinement", "1", "--quiet"],
        cwd=directory,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert run.returncode == 0, run.stdout + run.stderr
    for output in (f"{name}.msh", f"{name}_pressure.png", f"{name}_summary.txt"):
        assert (directory / output).stat().st_size > 0, output
    assert (directory / f"{name}_pressure.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert len(list((directory / "vtk_output").glob("Structure_0_*.vtu"))) == 4
    summary = (directory / f"{name}_summary.txt").read_text()
    assert "all steps converged" in summary
    assert summary in run.stdout


def study(
    example: Path,
    module: ModuleType,
    directory: Path,
    levels: tuple[int, ...],
    errors: Callable[[Any], str],
    quantities: tuple[str, str],
) -> list[Any]:
    """Run ``module`` at each level in a folder of its own; print the errors and observed orders.

    ``errors(result)`` is the errors' text of a level's line; ``quantities`` names the two
    whose ``<name>_error`` give the observed orders (the width, "b" or "a", and "p0").
    """
    results = []
    for level in levels:
        run_dir = directory / f"refinement_{level}"
        run_dir.mkdir()
        copy_inputs(example, run_dir)
        results.append(module.run(run_dir, level))
    for result in results:
        print(
            f"refinement {result.refinement}: h = {result.spacing:.4g}, {errors(result)}, "
            f"Newton {sum(result.iterations)}, {result.wall_time:.1f} s"
        )
    for coarse, fine in zip(results[:-1], results[1:], strict=True):
        ratio = coarse.spacing / fine.spacing
        orders = [
            f"{name} {math.log(_error(coarse, name) / _error(fine, name)) / math.log(ratio):.2f}"
            for name in quantities
        ]
        print(f"observed order {coarse.refinement}->{fine.refinement}: {', '.join(orders)}")
    return results


def _error(result: Any, name: str) -> float:
    return float(getattr(result, f"{name}_error"))
