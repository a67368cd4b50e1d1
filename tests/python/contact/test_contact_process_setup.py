"""The contact processes set up the reference cases' interfaces as docs/input_layer.md §3–4 says.

Each case is initialised through the analysis (solver variables and DoFs, mdpa, materials,
processes) and its first step's search is run; then the Contact part (generated interface
conditions, SLAVE / MASTER flags), the pairs in ComputingContact (names from the decoder),
the pair properties and the ProcessInfo values are checked.
"""

from __future__ import annotations

from pathlib import Path

import pytest

import contact_app as ca
from contact_app.analysis import StructuralMechanicsAnalysis
from contact_app.analysis.reporting import Reporter
from contact_app.parameters import Parameters

CASES_DIR = Path(__file__).resolve().parents[3].parent / "shared" / "kratos_cases"
pytestmark = pytest.mark.skipif(not CASES_DIR.is_dir(), reason="../shared/kratos_cases missing")


def _initialised(case: str, edit=None) -> StructuralMechanicsAnalysis:
    path = CASES_DIR / f"{case}_parameters.json"
    parameters = Parameters.from_file(path)
    parameters.AddValue("output_processes", {})
    parameters["processes"].AddValue("json_check_process", [])
    if edit is not None:
        edit(parameters)
    analysis = StructuralMechanicsAnalysis(
        ca.Model(), parameters, base_dir=path.parent, reporter=Reporter(quiet=True)
    )
    analysis.Initialize()
    analysis.time = analysis._GetSolver().AdvanceInTime(analysis.time)
    analysis.InitializeSolutionStep()
    return analysis


def _without_mpc_solver(parameters: Parameters) -> None:
    """The MPC solver is not available yet: a structural solver with the MPC variables instead."""
    solver = parameters["solver_settings"]
    solver.RemoveValue("mpc_contact_settings")
    solver.AddValue("auxiliary_variables_list", ["NORMAL", "NODAL_H", "WEIGHTED_GAP"])


def _counts(part: ca.ModelPart) -> tuple[int, int]:
    slave = sum(1 for c in part.Conditions if c.Is(ca.SLAVE))
    master = sum(1 for c in part.Conditions if c.Is(ca.MASTER))
    return slave, master


@pytest.mark.parametrize(
    ("case", "interface", "pairs", "local_system"),
    [
        (
            "ALM_frictionless_contact_test_2D/hyper_simple_patch_test",
            (1, 1),
            1,
            (10, "LAGRANGE_MULTIPLIER_CONTACT_PRESSURE"),
        ),
        (
            "ALM_frictionless_contact_test_3D/3D_contact_simplest_patch_matching_slope_test",
            (1, 1),
            1,
            (28, "LAGRANGE_MULTIPLIER_CONTACT_PRESSURE"),
        ),
        (
            "ALM_frictional_contact_test_2D/hyper_simple_patch_test",
            (1, 1),
            1,
            (12, "VECTOR_LAGRANGE_MULTIPLIER_Y"),
        ),
        (
            "penalty_frictionless_contact_test_2D/hyper_simple_patch_test",
            (1, 1),
            1,
            (8, "DISPLACEMENT_Y"),
        ),
        (
            "penalty_frictional_contact_test_2D/perfect_stick_hyper_simple_patch_test",
            (1, 1),
            1,
            (8, "DISPLACEMENT_Y"),
        ),
        (
            "mesh_tying_test/simple_patch_test_2D",
            (4, 2),
            None,
            (12, "VECTOR_LAGRANGE_MULTIPLIER_Y"),
        ),
        (
            "mpc_contact_tests/2D_contact_simplest_patch_matching_test",
            (1, 1),
            1,
            (8, "DISPLACEMENT_Y"),
        ),
    ],
)
def test_interface_and_pairs_of_the_reference_cases(case, interface, pairs, local_system) -> None:
    analysis = _initialised(case, _without_mpc_solver if case.startswith("mpc") else None)
    main = analysis.model.GetModelPart("Structure")
    contact = main.GetSubModelPart("Contact")
    sub = contact.GetSubModelPart("ContactSub0")
    assert _counts(sub) == interface
    for condition in sub.Conditions:
        assert condition.Is(ca.INTERFACE)
    computing = main.GetSubModelPart("ComputingContact")
    created = list(computing.Conditions)
    if pairs is not None:
        assert len(created) == pairs
    assert created, "no pair was created"
    for pair in created:
        # The registered class is recognised by its local system: size and last DoF.
        size, last_dof = local_system
        dofs = pair.GetDofList(main.ProcessInfo)
        assert len(dofs) == size
        assert dofs[-1].GetVariable().Name() == last_dof
        assert pair.IsPaired()
        properties = pair.Properties
        assert properties[ca.INTEGRATION_ORDER_CONTACT] == 2
    slave_nodes = [n for n in contact.Nodes if n.Is(ca.SLAVE)]
    assert slave_nodes and all(n.Is(ca.INTERFACE) for n in slave_nodes)


def test_alm_process_info_values() -> None:
    analysis = _initialised("ALM_frictionless_contact_test_2D/hyper_simple_patch_test")
    info = analysis.model.GetModelPart("Structure").ProcessInfo
    assert info[ca.INITIAL_PENALTY] > 0.0
    assert info[ca.SCALE_FACTOR] == pytest.approx(info[ca.INITIAL_PENALTY])
    assert info[ca.DISTANCE_THRESHOLD] < 1e24  # replaced by the mean nodal size at the first search
    assert info[ca.CONSIDER_NORMAL_VARIATION] == 0
    assert info[ca.ACTIVE_CHECK_FACTOR] == pytest.approx(0.01)
    contact = analysis.model.GetModelPart("Structure.Contact")
    for node in contact.Nodes:
        if node.Is(ca.SLAVE):
            assert node.GetValue(ca.INITIAL_PENALTY) == pytest.approx(info[ca.INITIAL_PENALTY])


def test_frictional_process_info_values() -> None:
    analysis = _initialised("ALM_frictional_contact_test_2D/hyper_simple_patch_test")
    info = analysis.model.GetModelPart("Structure").ProcessInfo
    assert info[ca.TANGENT_FACTOR] == pytest.approx(1.0)  # the 2019 default the reference cases use
    assert info[ca.OPERATOR_THRESHOLD] == pytest.approx(1e-3)
    # Frictional contact types update the normals every iteration.
    assert info[ca.CONSIDER_NORMAL_VARIATION] == 3
    main = analysis.model.GetModelPart("Structure")
    assert main.GetSubModelPart("Contact").Is(ca.SLIP)


def test_penalty_uses_the_scaled_automatic_penalty() -> None:
    alm = _initialised("penalty_frictionless_contact_test_2D/hyper_simple_patch_test")
    info = alm.model.GetModelPart("Structure").ProcessInfo
    assert info[ca.SCALE_FACTOR] == 1.0
    assert info[ca.INITIAL_PENALTY] > 1.0e4


def _contact_settings(parameters: Parameters) -> Parameters:
    return parameters["processes"]["contact_process_list"][0]["Parameters"]


@pytest.mark.parametrize(
    ("edit", "message"),
    [
        (lambda p: _contact_settings(p).AddValue("contact_typ", "Frictionless"), "contact_typ"),
        (
            lambda p: _contact_settings(p).AddValue("contact_model_part", {"0": ["Contact_Prt"]}),
            "Contact_Prt",
        ),
        (
            lambda p: _contact_settings(p).AddValue(
                "assume_master_slave", {"0": ["Parts_Parts_Auto3x"]}
            ),
            "Parts_Parts_Auto3x",
        ),
        (
            lambda p: _contact_settings(p).AddValue("contact_type", "Frictional"),
            "ALMContactFrictional",
        ),
        (lambda p: _contact_settings(p).AddValue("normal_variation", "nodal"), "normal_variation"),
    ],
)
def test_settings_errors_are_clear_and_early(edit, message) -> None:
    with pytest.raises(ca.InputError, match=message):
        _initialised("ALM_frictionless_contact_test_2D/hyper_simple_patch_test", edit)
