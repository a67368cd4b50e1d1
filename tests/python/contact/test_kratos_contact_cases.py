"""The reference contact cases of ../shared/kratos_cases, run from their unchanged parameters.

Each case runs through ``ca.analysis.run`` (the same path as ``contact-app run``) and must pass its
own ``from_json_check_result_process`` (absolute tolerance 1e-3). Because that tolerance is loose
for these small displacements, every checked column is compared again with a relative tolerance
of 1e-4 (an absolute floor of 1e-6 × the column's largest reference value keeps zeros meaningful);
the worst relative error per case is printed (``pytest -s``) and recorded as a test property.
The ALM frictionless cases are re-run as FrictionlessComponents, as the reference suite does.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import contact_app as ca
from contact_app.analysis import StructuralMechanicsAnalysis
from contact_app.analysis.reporting import Reporter
from contact_app.parameters import Parameters
from contact_app.processes.from_json_check_result_process import FromJsonCheckResultProcess

CASES_DIR = Path(__file__).resolve().parents[3].parent / "shared" / "kratos_cases"

CASES = {
    "alm_frictionless_2d_hyper_simple": "ALM_frictionless_contact_test_2D/hyper_simple_patch_test",
    "alm_frictionless_2d_taylor": "ALM_frictionless_contact_test_2D/taylor_patch_test",
    "alm_frictionless_3d_slope": (
        "ALM_frictionless_contact_test_3D/3D_contact_simplest_patch_matching_slope_test"
    ),
    "alm_frictional_2d_hyper_simple": "ALM_frictional_contact_test_2D/hyper_simple_patch_test",
    "penalty_frictionless_2d": "penalty_frictionless_contact_test_2D/hyper_simple_patch_test",
    "penalty_frictional_2d_stick": (
        "penalty_frictional_contact_test_2D/perfect_stick_hyper_simple_patch_test"
    ),
    "mesh_tying_2d": "mesh_tying_test/simple_patch_test_2D",
    "mpc_2d_matching": "mpc_contact_tests/2D_contact_simplest_patch_matching_test",
}
COMPONENTS = [name for name in CASES if name.startswith("alm_frictionless")]

#: Cases that do not (yet) agree with the reference, with the difference measured on 2026-11-21.
#: xfail(strict=True): a case that starts to agree fails the suite, so this list cannot go stale.
KNOWN_DIFFERENCES = {
    "alm_frictionless_2d_taylor": "passes its own check; strict: DISPLACEMENT_Y 0.7 % low on the "
    "punch (uniform), DISPLACEMENT_X 23 % at node 4 (|u| ~1e-5)",
    "alm_frictionless_3d_slope": "displacements exact; AUGMENTED_NORMAL_CONTACT_PRESSURE 0.33 % "
    "above the reference (1.00333e9 vs 1.00005e9), outside the case's tolerance",
    "alm_frictional_2d_hyper_simple": "passes its own check; strict: DISPLACEMENT_X 11 %",
    "penalty_frictionless_2d": "passes its own check; strict: 1.0e-3 relative",
    "penalty_frictional_2d_stick": "the slave nodes stick to the master (reference: they stay at "
    "x = 0 while the master slides 5.2e-3); the reference spreads the friction force with "
    "D - D_old (B2), which vanishes for small sliding",
    "mesh_tying_2d": "passes its own check; strict: DISPLACEMENT_X 1.35 %",
    "mpc_2d_matching": "the MPC contact solver (mpc_contact_settings) is not implemented yet",
}

pytestmark = pytest.mark.skipif(not CASES_DIR.is_dir(), reason="../shared/kratos_cases missing")


def _parameters(case: str, components: bool) -> Parameters:
    parameters = Parameters.from_file(CASES_DIR / f"{CASES[case]}_parameters.json")
    parameters.AddValue("output_processes", {})
    if components:
        solver = parameters["solver_settings"]
        solver["contact_settings"]["mortar_type"].SetString("ALMContactFrictionlessComponents")
        for process in parameters["processes"]["contact_process_list"]:
            process["Parameters"]["contact_type"].SetString("FrictionlessComponents")
    return parameters


def _check_processes(
    analysis: ca.analysis.StructuralMechanicsAnalysis,
) -> list[FromJsonCheckResultProcess]:
    return [p for p in analysis._GetListOfProcesses() if isinstance(p, FromJsonCheckResultProcess)]


def _strict_relative_errors(analysis, parameters: Parameters) -> dict[str, float]:
    """Worst relative error per checked column at the last reference time (floor 1e-6 × max)."""
    worst: dict[str, float] = {}
    for block in parameters["processes"]["json_check_process"]:
        settings = block["Parameters"]
        part = analysis.model.GetModelPart(settings["model_part_name"].GetString())
        historical = not settings.Has("historical_value") or settings["historical_value"].GetBool()
        path = CASES_DIR / settings["input_file_name"].GetString()
        data = json.loads(path.read_text())
        for name in settings["check_variables"].GetStringArray():
            variable = ca.get_variable(name)
            values = {}
            for node in part.Nodes:
                key = f"NODE_{node.Id}"
                if key not in data or name not in data[key]:
                    continue
                series = data[key][name]
                values[node.Id] = (
                    node.GetSolutionStepValue(variable) if historical else node.GetValue(variable),
                    series[-1],
                )
            if not values:
                continue
            scale = max(abs(b) for _, b in values.values())
            floor = 1.0e-6 * scale if scale > 0.0 else 1.0e-12
            errors = [abs(a - b) / max(abs(a), abs(b), floor) for a, b in values.values()]
            worst[name] = max(errors)
    return worst


def _param(name: str, components: bool) -> object:
    marks = []
    if name in KNOWN_DIFFERENCES:
        marks.append(pytest.mark.xfail(strict=True, reason=KNOWN_DIFFERENCES[name]))
    label = f"{name}_components" if components else name
    return pytest.param(name, components, marks=marks, id=label)


@pytest.mark.kratos_reference
@pytest.mark.parametrize(
    ("case", "components"),
    [_param(name, False) for name in CASES] + [_param(name, True) for name in COMPONENTS],
)
def test_reference_case_passes_its_checks(case: str, components: bool, record_property) -> None:
    parameters = _parameters(case, components)
    path = CASES_DIR / f"{CASES[case]}_parameters.json"
    analysis = StructuralMechanicsAnalysis(
        ca.Model(), parameters, base_dir=path.parent, reporter=Reporter(quiet=True)
    )
    analysis.Run()
    checks = _check_processes(analysis)
    assert checks, "the case has no from_json_check_result_process"
    strict = _strict_relative_errors(analysis, parameters)
    worst = max(strict.values()) if strict else 0.0
    label = f"{case} (components)" if components else case
    print(f"\n{label}: worst relative error {worst:.3e} {strict}")
    record_property("worst_relative_error", worst)
    assert worst < 1.0e-4, strict
