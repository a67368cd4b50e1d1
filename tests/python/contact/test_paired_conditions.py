"""Paired contact conditions from Python: creation, geometries, local system and errors."""

import numpy as np
import pytest

import contact_app as ca


def _pair_model() -> tuple[ca.ModelPart, ca.Properties]:
    """Two facing unit segments, 0.01 apart, as slave (top of the lower body) and master."""
    model = ca.Model()
    mp = model.CreateModelPart("Contact")
    for variable in (
        ca.DISPLACEMENT,
        ca.NORMAL,
        ca.WEIGHTED_GAP,
        ca.LAGRANGE_MULTIPLIER_CONTACT_PRESSURE,
    ):
        mp.AddNodalSolutionStepVariable(variable)
    coordinates = {1: (0.0, 0.0), 2: (1.0, 0.0), 3: (1.0, 0.01), 4: (0.0, 0.01)}
    for node_id, (x, y) in coordinates.items():
        node = mp.CreateNewNode(node_id, x, y, 0.0)
        for dof in (ca.DISPLACEMENT_X, ca.DISPLACEMENT_Y, ca.LAGRANGE_MULTIPLIER_CONTACT_PRESSURE):
            node.AddDof(dof)
    props = mp.CreateNewProperties(1)
    props[ca.INTEGRATION_ORDER_CONTACT] = 2
    mp.ProcessInfo[ca.SCALE_FACTOR] = 1.0
    for node_id in (1, 2):
        node = mp.GetNode(node_id)
        node.SetSolutionStepValue(ca.NORMAL, 0, [0.0, 1.0, 0.0])  # slave normal towards the master
        node.SetValue(ca.INITIAL_PENALTY, 100.0)
        node.Set(ca.ACTIVE, True)
    return mp, props


def test_paired_condition_has_its_slave_and_master_faces_and_local_system() -> None:
    mp, props = _pair_model()
    name = "ALMFrictionlessMortarContactCondition2D2N"
    condition = mp.CreateNewPairedCondition(name, 1, [1, 2], [3, 4], props)
    condition.SetValue(ca.NORMAL, [0.0, 1.0, 0.0])
    assert condition.IsPaired()
    assert [n.Id for n in condition.GetParentGeometry()] == [1, 2]
    assert [n.Id for n in condition.GetPairedGeometry()] == [3, 4]
    info = mp.ProcessInfo
    condition.Initialize(info)
    lhs, rhs = condition.CalculateLocalSystem(info)
    assert lhs.shape == (10, 10) and rhs.shape == (10,)
    # [master u, slave u, lambda]: the multiplier rows of active nodes hold k * weighted gap.
    dofs = condition.GetDofList(info)
    assert [d.Id() for d in dofs][:4] == [3, 3, 4, 4]
    assert dofs[8].GetVariable().Name() == "LAGRANGE_MULTIPLIER_CONTACT_PRESSURE"
    assert np.all(np.isfinite(lhs))
    condition.AddExplicitContribution(info)
    gaps = [mp.GetNode(i).GetSolutionStepValue(ca.WEIGHTED_GAP) for i in (1, 2)]
    # Matching faces, gap 0.01, dual multipliers: weighted gap = 0.01 * integral of N_j = 0.005.
    np.testing.assert_allclose(np.abs(gaps), [0.005, 0.005], rtol=1e-10)


def test_paired_condition_errors_name_the_problem() -> None:
    mp, props = _pair_model()
    with pytest.raises(ca.InputError, match="is not a paired"):
        mp.CreateNewPairedCondition("LineCondition2D2N", 1, [1, 2], [3, 4], props)
    with pytest.raises(
        ca.InputError, match='did you mean "ALMFrictionlessMortarContactCondition2D2N"'
    ):
        mp.CreateNewPairedCondition(
            "ALMFrictionlesMortarContactCondition2D2N", 1, [1, 2], [3, 4], props
        )
    with pytest.raises(ca.InputError, match="no node with id 9"):
        mp.CreateNewPairedCondition(
            "ALMFrictionlessMortarContactCondition2D2N", 1, [1, 9], [3, 4], props
        )
    plain = mp.CreateNewCondition("LineCondition2D2N", 5, [1, 2], props)
    with pytest.raises(ca.InputError, match="not a paired condition"):
        plain.GetPairedGeometry()
