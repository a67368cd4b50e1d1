"""An element inverted inside a Newton iteration fails the step, which is cut, not the run.

A 2 × 2 block of plane-strain Neo-Hookean quadrilaterals, bottom held, top pressed down by 60 % in
one step: the first iterate of that step turns an element inside out (det J < 0 for the updated
Lagrangian element, det F < 0 in the law for the total Lagrangian one), while ten sub-steps of 6 %
converge. contact_app cuts such a step by default (``cut_step_on_inverted_element``).
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from cli_runner import run_cli
from process_descriptors import hold_displacement

import contact_app as ca

SQUEEZE = 0.6


def _write_block(folder: Path, element: str, **solver_settings: Any) -> Path:
    """block.mdpa (n × n quads on the unit square), materials and ProjectParameters.json."""
    n = 2
    node = {(i, j): j * (n + 1) + i + 1 for j in range(n + 1) for i in range(n + 1)}
    lines = ["Begin Properties 1", "End Properties", "Begin Nodes"]
    lines += [f"  {k} {i / n} {j / n} 0.0" for (i, j), k in node.items()]
    lines += ["End Nodes", f"Begin Elements {element}"]
    quads = [
        [node[(i, j)], node[(i + 1, j)], node[(i + 1, j + 1)], node[(i, j + 1)]]
        for j in range(n)
        for i in range(n)
    ]
    lines += [f"  {e} 1 " + " ".join(map(str, q)) for e, q in enumerate(quads, 1)]
    lines.append("End Elements")
    parts = {
        "Parts_block": (sorted(node.values()), range(1, len(quads) + 1)),
        "bottom": ([node[(i, 0)] for i in range(n + 1)], ()),
        "top": ([node[(i, n)] for i in range(n + 1)], ()),
    }
    for name, (nodes, elements) in parts.items():
        lines += [f"Begin SubModelPart {name}", "  Begin SubModelPartNodes"]
        lines += [f"    {k}" for k in nodes] + ["  End SubModelPartNodes"]
        lines += ["  Begin SubModelPartElements"] + [f"    {e}" for e in elements]
        lines += ["  End SubModelPartElements", "End SubModelPart"]
    (folder / "block.mdpa").write_text("\n".join(lines) + "\n")
    law = {"name": "HyperElasticPlaneStrain2DLaw"}
    variables = {"YOUNG_MODULUS": 1000.0, "POISSON_RATIO": 0.3, "THICKNESS": 1.0}
    materials = {
        "properties": [
            {
                "model_part_name": "Structure.Parts_block",
                "properties_id": 1,
                "Material": {"constitutive_law": law, "Variables": variables},
            }
        ]
    }
    (folder / "block_materials.json").write_text(json.dumps(materials))
    solver = {
        "model_part_name": "Structure",
        "domain_size": 2,
        "solver_type": "Static",
        "model_import_settings": {"input_type": "mdpa", "input_filename": "block"},
        "material_import_settings": {"materials_filename": "block_materials.json"},
        "time_stepping": {"time_step": 1.0},
        "max_iteration": 20,
        "residual_relative_tolerance": 1e-9,
        "residual_absolute_tolerance": 1e-12,
        **solver_settings,
    }

    parameters = {
        "problem_data": {"problem_name": "block", "start_time": 0.0, "end_time": 1.0},
        "solver_settings": solver,
        "processes": {
            "constraints_process_list": [
                hold_displacement("bottom", [True, True, True], [0.0, 0.0, 0.0]),
                hold_displacement("top", [True, True, True], [0.0, f"-{SQUEEZE}*t", 0.0]),
            ]
        },
        "output_processes": {},
    }
    path = folder / "ProjectParameters.json"
    path.write_text(json.dumps(parameters, indent=1))
    return path


ELEMENTS = {
    "UpdatedLagrangianElement2D4N": "is inverted in the current configuration: det J = -",
    "TotalLagrangianElement2D4N": "HyperElasticPlaneStrain2DLaw: det F = -",
}


@pytest.mark.parametrize("element", ELEMENTS)
def test_an_inverted_element_cuts_the_step_and_the_run_finishes(
    element: str, tmp_path: Path
) -> None:
    _write_block(tmp_path, element)
    result = run_cli("run", "ProjectParameters.json", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    # The iteration failed, named with the element, the value and TIME; then the step was cut.
    assert f"Newton iteration 1 failed: {element} #" in result.stderr
    assert ELEMENTS[element] in result.stderr
    assert "(TIME = 1)" in result.stderr
    assert "the step is cut (split_factor 10, max_number_splits 3) because of an inverted" in (
        result.stderr
    )
    assert "cut_step_on_inverted_element is true by default" in result.stderr
    assert "all converged" in result.stdout
    assert "step cutting: 1 step(s) redone in 10 sub-steps" in result.stdout


@pytest.mark.parametrize("element", ELEMENTS)
def test_an_inverted_element_stops_the_run_when_cutting_is_off(
    element: str, tmp_path: Path
) -> None:
    _write_block(tmp_path, element, cut_step_on_inverted_element=False)
    result = run_cli("run", "ProjectParameters.json", cwd=tmp_path)
    assert result.returncode == 1, result.stderr
    error = result.stderr[result.stderr.index("error: ") :]
    assert f"error: step 1 (TIME = 1) did not converge: {element} #" in error
    assert ELEMENTS[element] in error
    assert "cut_step_on_inverted_element: true" in error  # the fix names the setting
    assert "Traceback" not in result.stderr


def test_the_sub_stepped_state_is_the_compressed_block(tmp_path: Path) -> None:
    """The cut step ends at TIME 1 with the top where the load put it."""
    path = _write_block(tmp_path, "UpdatedLagrangianElement2D4N")
    analysis = ca.analysis.run(path, quiet=True)
    part = analysis.model.GetModelPart("Structure")
    assert part.ProcessInfo[ca.TIME] == pytest.approx(1.0)
    top = part.GetSubModelPart("top").Nodes
    assert [n.GetSolutionStepValue(ca.DISPLACEMENT_Y) for n in top] == pytest.approx([-SQUEEZE] * 3)
    assert all(e.GetGeometry().Area() > 0.0 for e in part.Elements)


def test_the_python_exception_carries_element_value_and_time(tmp_path: Path) -> None:
    """Solving the step directly raises InvertedElementError (a ConvergenceError) with fields."""
    path = _write_block(tmp_path, "UpdatedLagrangianElement2D4N")
    analysis = ca.analysis.StructuralMechanicsAnalysis(
        ca.Model(), ca.parameters.Parameters.from_file(path), base_dir=tmp_path
    )
    analysis.Initialize()
    solver = analysis._GetSolver()
    analysis.time = solver.AdvanceInTime(analysis.time)
    analysis.InitializeSolutionStep()
    solver.Predict()
    with pytest.raises(ca.InvertedElementError) as caught:
        solver.GetSolutionStrategy().SolveSolutionStep()
    failure = caught.value
    assert isinstance(failure, ca.ConvergenceError)
    assert failure.element_id in (1, 2, 3, 4)
    assert failure.quantity == "det J" and failure.value < 0.0
    assert failure.time == pytest.approx(1.0)
    assert not solver.SolveSolutionStep()  # the solver turns it into "not converged"
    assert solver.last_failure is not None
