"""MechanicalSolver: defaults, deprecated keys, validation, time stepping, strategy construction."""

from __future__ import annotations

import logging
from typing import Any

import pytest
from analysis_cases import solver_settings

import contact_app as ca
from contact_app.analysis.solvers import StaticMechanicalSolver
from contact_app.parameters import Parameters


def _settings(**changes: Any) -> Parameters:
    settings = solver_settings("Static", 2, 0.1, **changes)
    return Parameters(settings, source="case.json", path=("solver_settings",))


def _solver(**changes: Any) -> StaticMechanicalSolver:
    return StaticMechanicalSolver(ca.Model(), _settings(**changes))


def _square(solver: StaticMechanicalSolver) -> ca.ModelPart:
    """One unit plane-strain quad, left edge clamped, right edge pulled (ready for AddDofs)."""
    part = solver.main_model_part
    solver.AddVariables()
    for node_id, (x, y) in enumerate([(0, 0), (1, 0), (1, 1), (0, 1)], start=1):
        part.CreateNewNode(node_id, float(x), float(y), 0.0)
    props = part.CreateNewProperties(1)
    props[ca.YOUNG_MODULUS] = 100.0
    props[ca.POISSON_RATIO] = 0.0
    props[ca.THICKNESS] = 1.0
    props[ca.CONSTITUTIVE_LAW] = ca.create_constitutive_law("LinearElasticPlaneStrain2DLaw")
    part.CreateNewElement("SmallDisplacementElement2D4N", 1, [1, 2, 3, 4], props)
    return part


def test_every_documented_default_is_assigned() -> None:
    solver = _solver()
    settings = solver.settings
    expected = {
        "computing_sub_model_part_name": "",
        "echo_level": 0,
        "buffer_size": 2,
        "analysis_type": "non_linear",
        "reform_dofs_at_each_step": False,
        "compute_reactions": True,
        "clear_storage": False,
        "move_mesh_flag": True,
        "multi_point_constraints_used": True,
        "convergence_criterion": "residual_criterion",
        "displacement_relative_tolerance": 1e-4,
        "displacement_absolute_tolerance": 1e-9,
        "residual_relative_tolerance": 1e-4,
        "residual_absolute_tolerance": 1e-9,
        "max_iteration": 10,
        "rotation_dofs": False,
        "use_old_stiffness_in_first_iteration": False,
        "auxiliary_variables_list": [],
    }
    for key, value in expected.items():
        assert settings[key].GetValue() == value, key
    assert settings["builder_and_solver_settings"]["type"].GetString() == "block"
    assert settings["solving_strategy_settings"]["type"].GetString() == "newton_raphson"
    assert solver.main_model_part.ProcessInfo[ca.DOMAIN_SIZE] == 2


def test_deprecated_keys_are_converted_with_one_warning_each(
    caplog: pytest.LogCaptureFixture,
) -> None:
    with caplog.at_level(logging.WARNING, logger="contact_app"):
        solver = _solver(
            block_builder=False,
            line_search=True,
            use_computing_model_part=True,
            computing_model_part_name="computing_domain",
            problem_domain_sub_model_part_list=["a"],
            processes_sub_model_part_list=["b"],
        )
    settings = solver.settings
    assert settings["builder_and_solver_settings"]["type"].GetString() == "elimination"
    assert settings["solving_strategy_settings"]["type"].GetString() == "line_search"
    for key in (
        "block_builder",
        "line_search",
        "use_computing_model_part",
        "computing_model_part_name",
    ):
        assert not settings.Has(key)
    assert len(caplog.records) == 6
    assert "case.json › solver_settings › block_builder is deprecated" in caplog.text


def test_builder_settings_without_type_use_the_legacy_flags() -> None:
    solver = _solver(builder_and_solver_settings={"use_block_builder": False})
    assert solver.settings["builder_and_solver_settings"]["type"].GetString() == "elimination"
    with pytest.raises(ca.ConfigurationError, match="Lagrange"):
        _solver(builder_and_solver_settings={"use_lagrange_BS": True})
    with pytest.raises(ca.InputError, match="both the deprecated block_builder"):
        _solver(block_builder=True, builder_and_solver_settings={"type": "block"})


@pytest.mark.parametrize(
    ("changes", "error", "message"),
    [
        ({"max_iterations": 3}, ca.InputError, 'did you mean "max_iteration"'),
        ({"max_iteration": 0}, ca.InputError, '"max_iteration" is 0'),
        ({"max_iteration": 2.5}, ca.InputError, '"max_iteration" has the wrong type'),
        ({"domain_size": 1}, ca.InputError, "domain_size is 1"),
        ({"model_part_name": ""}, ca.InputError, "model_part_name is empty"),
        ({"analysis_type": "nonlinear"}, ca.InputError, 'did you mean "non_linear"'),
        (
            {"residual_relative_tolerance": -1.0},
            ca.InputError,
            '"residual_relative_tolerance" is -1.0',
        ),
        ({"rotation_dofs": True}, ca.ConfigurationError, "rotation DoFs"),
        ({"use_old_stiffness_in_first_iteration": True}, ca.ConfigurationError, "not supported"),
        ({"time_stepping": {}}, ca.InputError, "exactly one of time_step"),
        (
            {"time_stepping": {"time_step": 0.1, "time_step_table": [[0, 1]]}},
            ca.InputError,
            "found time_step, time_step_table",
        ),
        ({"time_stepping": {"time_step": 0.0}}, ca.InputError, '"time_step" is 0.0'),
        (
            {"time_stepping": {"time_step_table": [[0.0, 1.0], [0.0, 2.0]]}},
            ca.InputError,
            "do not increase",
        ),
        ({"time_stepping": {"time_step_table": [[0.0, -1.0]]}}, ca.InputError, "dt ≤ 0"),
        ({"time_stepping": {"time_step_table": [[0.0, 1.0, 2.0]]}}, ca.InputError, "rows of"),
        (
            {"solving_strategy_settings": {"type": "arc_length"}},
            ca.ConfigurationError,
            "arc-length",
        ),
        (
            {"solving_strategy_settings": {"type": "newton"}},
            ca.InputError,
            'did you mean "newton_raphson"',
        ),
        (
            {
                "solving_strategy_settings": {
                    "type": "line_search",
                    "advanced_settings": {"max_alpha": "2"},
                }
            },
            ca.InputError,
            '"max_alpha" has the wrong type',
        ),
        (
            {"builder_and_solver_settings": {"type": "blocks"}},
            ca.InputError,
            'did you mean "block"',
        ),
        (
            {"linear_solver_settings": {"solver_type": "super_lux"}},
            ca.InputError,
            "solver_settings › linear_solver_settings › solver_type",
        ),
        ({"linear_solver_settings": {"tolerance": 0.0}}, ca.InputError, '"tolerance" is 0.0'),
        (
            {"model_import_settings": {"input_type": "rest", "input_filename": "case"}},
            ca.InputError,
            'missing required key "restart_load_file_label"',
        ),
        (
            {
                "model_import_settings": {
                    "input_type": "rest",
                    "input_filename": "no_such_case",
                    "restart_load_file_label": "1.0",
                }
            },
            ca.InputError,
            "no_such_case__restart_files",
        ),
        (
            {"model_import_settings": {"input_type": "mdpa"}},
            ca.InputError,
            'missing required key "input_filename"',
        ),
        (
            {"auxiliary_variables_list": ["DISPLACEMNT"]},
            ca.InputError,
            'did you mean "DISPLACEMENT"',
        ),
        (
            {"auxiliary_dofs_list": ["TEMPERATURE"]},
            ca.InputError,
            "1 auxiliary DoFs but 0 reactions",
        ),
        (
            {"material_import_settings": {"custom_reader": "x"}},
            ca.ConfigurationError,
            "custom materials reader",
        ),
        ({"scheme_type": "bossak"}, ca.InputError, 'unknown key "scheme_type"'),
    ],
)
def test_invalid_settings_are_rejected(
    changes: dict[str, Any], error: type[Exception], message: str
) -> None:
    with pytest.raises(error, match=message):
        _solver(**changes)


def test_missing_domain_size_is_reported() -> None:
    settings = _settings()
    settings.RemoveValue("domain_size")
    with pytest.raises(ca.InputError, match='missing required key "domain_size"'):
        StaticMechanicalSolver(ca.Model(), settings)


def test_time_step_table_and_advance_in_time() -> None:
    solver = _solver(time_stepping={"time_step_table": [[0.0, 0.1], [1.0, 0.3]]})
    info = solver.main_model_part.ProcessInfo
    assert solver.ComputeDeltaTime() == pytest.approx(0.1)
    assert solver.AdvanceInTime(0.0) == pytest.approx(0.1)
    assert (info[ca.STEP], info[ca.TIME], info[ca.DELTA_TIME]) == (
        1,
        pytest.approx(0.1),
        pytest.approx(0.1),
    )
    info[ca.TIME] = 0.5
    assert solver.ComputeDeltaTime() == pytest.approx(0.2)
    info[ca.TIME] = 2.0  # beyond the table: linear extrapolation, as Kratos tables do
    assert solver.ComputeDeltaTime() == pytest.approx(0.5)


def test_time_step_table_extrapolated_below_zero_is_an_error() -> None:
    solver = _solver(time_stepping={"time_step_table": [[0.0, 1.0], [1.0, 0.5]]})
    solver.main_model_part.ProcessInfo[ca.TIME] = 3.0
    with pytest.raises(ca.InputError, match="time_step_table gives Δt = -0.5 at TIME = 3.0"):
        solver.ComputeDeltaTime()


def test_time_step_intervals_outside_every_interval_is_an_error() -> None:
    solver = _solver(
        time_stepping={"time_step_intervals": {"a": {"interval": [0.0, 1.0], "time_step": 0.5}}}
    )
    solver.main_model_part.ProcessInfo[ca.TIME] = 1.5
    with pytest.raises(
        ca.InputError, match="no interval of time_step_intervals contains TIME = 1.5"
    ):
        solver.ComputeDeltaTime()


@pytest.mark.parametrize(
    ("changes", "strategy", "builder"),
    [
        ({}, ca.ResidualBasedNewtonRaphsonStrategy, "block"),
        ({"line_search": True}, ca.LineSearchStrategy, "block"),
        (
            {"builder_and_solver_settings": {"type": "elimination"}},
            ca.ResidualBasedNewtonRaphsonStrategy,
            "elimination",
        ),
        ({"analysis_type": "linear"}, ca.SolvingStrategy, "block"),
    ],
)
def test_strategy_and_builder_follow_the_settings(
    changes: dict[str, Any], strategy: type, builder: str
) -> None:
    solver = _solver(**changes)
    part = _square(solver)
    solver.PrepareModelPart()
    solver.AddDofs()
    solver.Initialize()
    assert isinstance(solver.GetSolutionStrategy(), strategy)
    if changes.get("analysis_type") == "linear":
        assert not isinstance(solver.GetSolutionStrategy(), ca.ResidualBasedNewtonRaphsonStrategy)
        assert solver.GetConvergenceCriterion() is None
    assert solver.GetBuilderAndSolver().Info() == builder
    for node in part.Nodes:
        if node.X0 == 0.0:
            node.Fix(ca.DISPLACEMENT_X)
            node.Fix(ca.DISPLACEMENT_Y)
        else:
            node.Fix(ca.DISPLACEMENT_X)
            node.SetSolutionStepValue(ca.DISPLACEMENT_X, 0, 0.01)
    solver.AdvanceInTime(0.0)
    assert solver.Solve()
    # E = 100, ν = 0 in plane strain: uniform strain 0.01, reaction = 100 * 0.01 * 1
    right = sum(n.GetSolutionStepValue(ca.REACTION_X) for n in part.Nodes if n.X0 == 1.0)
    assert right == pytest.approx(1.0, rel=1e-10)


def test_buffer_is_sized_and_filled_without_moving_time() -> None:
    solver = _solver(buffer_size=3)
    part = _square(solver)
    part.GetNode(2).SetSolutionStepValue(ca.DISPLACEMENT_X, 0, 0.5)
    solver.PrepareModelPart()
    assert part.GetBufferSize() == 3
    assert part.GetNode(2).GetSolutionStepValue(ca.DISPLACEMENT_X, 2) == 0.5
    assert (part.ProcessInfo[ca.STEP], part.ProcessInfo[ca.TIME]) == (0, 0.0)
    assert _solver(buffer_size=1).GetMinimumBufferSize() == 2


def test_computing_sub_model_part_must_exist() -> None:
    solver = _solver(computing_sub_model_part_name="computing_domian")
    solver.main_model_part.CreateSubModelPart("computing_domain")
    with pytest.raises(ca.InputError, match='did you mean "computing_domain"'):
        solver.GetComputingModelPart()


def test_variables_and_dofs_of_the_static_solver() -> None:
    solver = _solver(auxiliary_dofs_list=["TEMPERATURE"], auxiliary_reaction_list=["NODAL_H"])
    part = _square(solver)
    for name in (
        "DISPLACEMENT",
        "REACTION",
        "LINE_LOAD",
        "SURFACE_LOAD",
        "POINT_LOAD",
        "TEMPERATURE",
    ):
        assert part.HasNodalSolutionStepVariable(ca.get_variable(name)), name
    assert not part.HasNodalSolutionStepVariable(ca.VELOCITY)
    solver.AddDofs()
    node = part.GetNode(1)
    for name in ("DISPLACEMENT_X", "DISPLACEMENT_Y", "DISPLACEMENT_Z", "TEMPERATURE"):
        assert node.HasDofFor(ca.get_variable(name)), name
