"""json_output_process: file layout, strict time_frequency, flags, resultants, round trip."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from conftest import build_plate, create, impose_displacement, run_steps

import contact_app as ca
from contact_app.processes.from_json_check_result_process import ResultCheckError


def _solve(plate: ca.ModelPart):  # noqa: ANN202 - small closure for run_steps
    return lambda time: impose_displacement(plate, time)


def _top_output(
    model: ca.Model, output: Path, variables: list[str], time_frequency: float, **parameters: Any
) -> Any:
    """A json_output_process of ``variables`` on "Structure.Top" writing ``output``."""
    return create(
        "json_output_process",
        {
            "output_variables": variables,
            **parameters,
            "output_file_name": str(output),
            "model_part_name": "Structure.Top",
            "time_frequency": time_frequency,
        },
        model,
    )


def test_json_output_layout_matches_the_kratos_results_files(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path
) -> None:
    output = tmp_path / "out" / "case_results.json"
    process = create(
        "json_output_process",
        {
            "output_variables": ["DISPLACEMENT", "REACTION_X"],
            "gauss_points_output_variables": ["VON_MISES_STRESS", "CAUCHY_STRESS_VECTOR"],
            "output_file_name": str(output),
            "model_part_name": "Structure.Body",
            "time_frequency": 0.0,
        },
        model,
    )
    process.ExecuteBeforeSolutionLoop()
    skeleton = json.loads(output.read_text())
    assert skeleton["TIME"] == [] and skeleton["NODE_5"] == {
        "DISPLACEMENT_X": [],
        "DISPLACEMENT_Y": [],
        "DISPLACEMENT_Z": [],
        "REACTION_X": [],
    }
    run_steps(plate, [process], [0.5, 1.0], _solve(plate))
    data = json.loads(output.read_text())
    assert data["TIME"] == [0.5, 1.0]
    assert data["NODE_9"]["DISPLACEMENT_X"] == pytest.approx([0.01, 0.02])
    assert data["NODE_9"]["DISPLACEMENT_Y"] == pytest.approx([-0.02, -0.04])
    assert data["NODE_9"]["REACTION_X"] == [0.0, 0.0]
    assert sorted(data["ELEMENT_1"]) == ["CAUCHY_STRESS_VECTOR", "VON_MISES_STRESS"]
    assert sorted(data["ELEMENT_1"]["VON_MISES_STRESS"]) == ["0", "1", "2", "3"]
    stresses = plate.GetElement(1).CalculateOnIntegrationPoints(
        ca.VON_MISES_STRESS, plate.ProcessInfo
    )
    assert data["ELEMENT_1"]["VON_MISES_STRESS"]["2"][1] == pytest.approx(stresses[2])
    assert len(data["ELEMENT_1"]["CAUCHY_STRESS_VECTOR"]["0"][1]) == 3


def test_json_output_time_frequency_is_strict(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path
) -> None:
    output = tmp_path / "results.json"
    process = _top_output(model, output, ["DISPLACEMENT_X"], 1.0)
    run_steps(plate, [process], [0.25 * k for k in range(1, 12)], _solve(plate))
    # counter: 0.25 ... 1.0 is not > 1.0; 1.25 is -> output at t = 1.25, then again 1.25 later
    assert json.loads(output.read_text())["TIME"] == [1.25, 2.5]


def test_json_output_flag_writes_null_where_the_flag_is_off(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path
) -> None:
    output = tmp_path / "results.json"
    process = _top_output(
        model,
        output,
        ["AUGMENTED_NORMAL_CONTACT_PRESSURE"],
        0.0,
        historical_value=False,
        check_for_flag="ACTIVE",
    )

    def contact(time: float) -> None:
        for node in plate.GetSubModelPart("Top").Nodes:
            node.SetValue(ca.AUGMENTED_NORMAL_CONTACT_PRESSURE, -node.Id * time)
            node.Set(ca.ACTIVE, node.Id == 9 or time > 1.5)

    run_steps(plate, [process], [1.0, 2.0], contact)
    data = json.loads(output.read_text())
    assert data["NODE_9"]["AUGMENTED_NORMAL_CONTACT_PRESSURE"] == [-9.0, -18.0]
    assert data["NODE_7"]["AUGMENTED_NORMAL_CONTACT_PRESSURE"] == [None, -14.0]


def test_json_output_resultant_sums_the_nodes(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path
) -> None:
    output = tmp_path / "results.json"
    process = _top_output(model, output, ["DISPLACEMENT"], 0.0, resultant_solution=True)
    run_steps(plate, [process], [1.0], _solve(plate))
    data = json.loads(output.read_text())
    assert set(data) == {"TIME", "RESULTANT"}
    assert data["RESULTANT"]["DISPLACEMENT_X"] == pytest.approx([0.01 * (0 + 1 + 2)])
    assert data["RESULTANT"]["DISPLACEMENT_Y"] == pytest.approx([-0.02 * 2 * 3])


def test_json_output_then_check_passes_and_a_perturbed_value_fails(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path
) -> None:
    output = tmp_path / "results.json"
    common = {"model_part_name": "Structure", "time_frequency": 0.0}
    writer = create(
        "json_output_process",
        {
            "output_variables": ["DISPLACEMENT_X", "DISPLACEMENT_Y"],
            "gauss_points_output_variables": ["VON_MISES_STRESS"],
            "output_file_name": str(output),
            **common,
        },
        model,
    )
    times = [0.5, 1.0, 1.5]
    run_steps(plate, [writer], times, _solve(plate))

    def checker() -> tuple[ca.ModelPart, object]:  # a fresh run of the same model
        rerun = ca.Model()
        return build_plate(rerun), create(
            "from_json_check_result_process",
            {
                "check_variables": ["DISPLACEMENT_X", "DISPLACEMENT_Y"],
                "gauss_points_check_variables": ["VON_MISES_STRESS"],
                "input_file_name": str(output),
                "relative_tolerance": 1e-12,
                "tolerance": 1e-14,
                **common,
            },
            rerun,
        )

    again, check = checker()
    run_steps(again, [check], times, lambda time: impose_displacement(again, time))
    assert check.checked_times == times
    assert check.worst_relative_errors == {
        "DISPLACEMENT_X": 0.0,
        "DISPLACEMENT_Y": 0.0,
        "VON_MISES_STRESS": 0.0,
    }

    again, check = checker()

    def perturbed(time: float) -> None:
        impose_displacement(again, time)
        again.GetNode(6).SetSolutionStepValue(ca.DISPLACEMENT_Y, 0, -0.02 * time * 1.0001)

    with pytest.raises(ResultCheckError, match="DISPLACEMENT_Y of node 6") as error:
        run_steps(again, [check], times, perturbed)
    assert "VON_MISES_STRESS of element" in str(error.value)  # the stresses changed too
    # |a - b| / max(|a|, |b|) = 1e-4 / 1.0001
    assert check.worst_relative_errors["DISPLACEMENT_Y"] == pytest.approx(1e-4 / 1.0001, rel=1e-9)


def test_json_output_needs_a_file_name(model: ca.Model, plate: ca.ModelPart) -> None:
    with pytest.raises(ca.InputError, match='missing key "output_file_name"'):
        create("json_output_process", {"model_part_name": "Structure"}, model)
