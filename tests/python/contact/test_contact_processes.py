"""Interface preprocessing, ALM helper processes and active-set utilities from Python."""

from pathlib import Path

import numpy as np
import pytest

import contact_app as ca

CASES_DIR = Path(__file__).resolve().parents[3].parent / "shared" / "kratos_cases"
PATCH_2D = CASES_DIR / "ALM_frictionless_contact_test_2D" / "hyper_simple_patch_test"


def _read_patch() -> tuple[ca.Model, ca.ModelPart]:
    """The 2D ALM hyper-simple patch test: two unit quads 0.001 apart, with NODAL_H stored."""
    model = ca.Model()
    root = model.CreateModelPart("Structure", 2)
    for variable in (ca.DISPLACEMENT, ca.NODAL_H, ca.WEIGHTED_GAP, ca.NORMAL):
        root.AddNodalSolutionStepVariable(variable)
    ca.ModelPartIO(str(PATCH_2D)).ReadModelPart(root)
    return model, root


@pytest.mark.skipif(not CASES_DIR.is_dir(), reason="../shared/kratos_cases missing")
def test_contact_processes_prepare_the_2d_patch_interface() -> None:
    _, root = _read_patch()
    contact = root.GetSubModelPart("Contact_Part")
    preprocess = ca.InterfacePreprocessCondition(root)
    created = preprocess.GenerateInterfacePart(
        contact, simplify_geometry=False, contact_property_id=0
    )
    assert created == 2
    assert preprocess.GenerateInterfacePart(contact) == 0  # reused, not duplicated
    for condition in contact.Conditions:
        normal = np.asarray(condition.GetGeometry().UnitNormal([0.0, 0.0, 0.0]))
        lower_body = condition.GetGeometry()[0].Id <= 4
        assert normal[1] == pytest.approx(1.0 if lower_body else -1.0)
        assert condition.Is(ca.INTERFACE)
    ca.FindNodalHProcess(root).Execute()
    assert root.GetNode(1).GetSolutionStepValue(ca.NODAL_H) == pytest.approx(1.0)
    assert ca.ContactUtilities.CalculateMinimalNodalH(contact) == pytest.approx(0.999)
    check = ca.NormalCheckProcess(contact, length_proportion=0.1)
    check.Execute()
    assert check.NumberOfFlippedConditions() == 0
    for node_id in (3, 4):
        root.GetNode(node_id).Set(ca.SLAVE, True)
    ca.MasterSlaveProcess(contact).Execute()
    slave = [c.Is(ca.SLAVE) for c in contact.Conditions]
    assert sorted(slave) == [False, True]


@pytest.mark.skipif(not CASES_DIR.is_dir(), reason="../shared/kratos_cases missing")
def test_degenerate_interface_face_is_named_with_its_model_part() -> None:
    _, root = _read_patch()
    contact = root.GetSubModelPart("Contact_Part")
    ca.InterfacePreprocessCondition(root).GenerateInterfacePart(contact)
    # Node 4 moved onto node 3: the interface line 3-4 of the lower block has no length.
    node = root.GetNode(4)
    node.X = node.X0 = 1.0
    expected = (
        r"condition \d+ \(Line2D2 with nodes \[3, 4\]\) of model part \"Structure.Contact_Part\" "
        "is a degenerate face, zero length: nodes 3 and 4 are at the same point"
    )
    with pytest.raises(ca.InputError, match=expected):
        ca.NormalCheckProcess(contact, length_proportion=0.1).Execute()


@pytest.mark.skipif(not CASES_DIR.is_dir(), reason="../shared/kratos_cases missing")
def test_alm_parameters_and_fast_init_from_python() -> None:
    _, root = _read_patch()
    contact = root.GetSubModelPart("Contact_Part")
    ca.InterfacePreprocessCondition(root).GenerateInterfacePart(contact, contact_property_id=1)
    root.GetProperties(1)[ca.YOUNG_MODULUS] = 200.0
    ca.FindNodalHProcess(root).Execute()
    ca.ALMVariablesCalculationProcess(
        contact, stiffness_factor=1.0, penalty_scale_factor=2.0
    ).Execute()
    # No side flags: both unit lines count for both sides, E = 200 and mean h = (1 + 0.999) / 2
    # (with the 1e-12 regularisations of the reference).
    tiny, area = 1e-12, 2.0
    expected = (200.0 * area / (area + tiny)) / ((1.0 + 0.999) / (area + tiny) + tiny)
    penalty = root.ProcessInfo[ca.INITIAL_PENALTY]
    assert penalty == pytest.approx(expected, rel=1e-14)
    assert root.ProcessInfo[ca.SCALE_FACTOR] == pytest.approx(2.0 * penalty, rel=1e-12)
    ca.ALMFastInit(contact).Execute()
    assert root.GetNode(3).GetValue(ca.INITIAL_PENALTY) == pytest.approx(penalty)
    assert root.GetNode(3).GetValue(ca.DYNAMIC_FACTOR) == 1.0


def test_active_set_utilities_from_python() -> None:
    model = ca.Model()
    root = model.CreateModelPart("Structure")
    root.AddNodalSolutionStepVariable(ca.WEIGHTED_GAP)
    root.AddNodalSolutionStepVariable(ca.LAGRANGE_MULTIPLIER_CONTACT_PRESSURE)
    contact = root.CreateSubModelPart("Contact")
    node = root.CreateNewNode(1, 0.0, 0.0, 0.0)
    contact.AddNodes([1])
    node.Set(ca.SLAVE, True)
    node.SetSolutionStepValue(ca.WEIGHTED_GAP, 0, -0.1)
    root.ProcessInfo[ca.SCALE_FACTOR] = 2.0
    root.ProcessInfo[ca.INITIAL_PENALTY] = 10.0
    root.ProcessInfo[ca.NL_ITERATION_NUMBER] = 1
    assert ca.ActiveSetUtilities.ComputeALMFrictionlessActiveSet(root) == 1
    assert node.Is(ca.ACTIVE)
    assert node.GetSolutionStepValue(ca.LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) == pytest.approx(-0.5)
    assert ca.ContactUtilities.CheckActivity(root, False)
    distance = ca.ContactUtilities.DistancePoints([0.0, 0.0, 0.0], [3.0, 4.0, 0.0])
    assert distance == pytest.approx(5.0)
    # Simplified semi-smooth Newton: the set is frozen after iteration 1.
    root.ProcessInfo[ca.NL_ITERATION_NUMBER] = 2
    node.SetSolutionStepValue(ca.WEIGHTED_GAP, 0, 1.0)
    assert ca.ActiveSetUtilities.ComputeALMFrictionlessActiveSet(root) == 0
    flips = ca.ActiveSetUtilities.ComputeALMFrictionalActiveSet(root, pure_slip=False)
    assert list(flips) == [0, 0]


def test_process_argument_errors_are_input_errors() -> None:
    model = ca.Model()
    part = model.CreateModelPart("Contact")
    with pytest.raises(ca.InputError, match="length_proportion"):
        ca.NormalCheckProcess(part, length_proportion=-1.0)
    with pytest.raises(ca.InputError, match="stiffness_factor"):
        ca.ALMVariablesCalculationProcess(part, stiffness_factor=0.0)
    nan, inf = float("nan"), float("inf")
    with pytest.raises(ca.InputError, match="length_proportion is nan"):
        ca.NormalCheckProcess(part, length_proportion=nan)
    with pytest.raises(ca.InputError, match="check_threshold is nan"):
        ca.NormalCheckProcess(part, check_threshold=nan)
    with pytest.raises(ca.InputError, match="positive and finite"):
        ca.ALMVariablesCalculationProcess(part, penalty_scale_factor=inf)
    with pytest.raises(ca.InputError, match="interface condition"):
        ca.ALMVariablesCalculationProcess(part).Execute()
