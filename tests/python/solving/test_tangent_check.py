"""The directional check of a whole model's tangent (NewtonRaphsonStrategy.CheckTangentAlong).

A v against central differences of the RHS along v at the current iterate, with what an
iteration refreshes before its build (criteria, contact normals and nodal sums) refreshed at
every perturbed state (docs/theory/structural.md §6 "Checking the assembled tangent"). On a
hyperelastic plate, whose tangent is exact, it must agree to round-off (measured 4e-11), zero
the fixed DoFs, and leave the state as it found it. (SmallDisplacementElement with that law is
not exact, 0.24: the law's tangent is dS/dE, the element differentiates in the small strain;
docs/theory/structural.md §6.) The contact strategy's refresh is checked in
tests/python/contact/test_contact_tangent_check.py.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_strategies import _clamp_and_pull, _newton, _plate

import contact_app as ca


def random_direction(size: int, seed: int = 3) -> np.ndarray:
    """A reproducible direction over ``size`` unknowns."""
    return np.random.default_rng(seed).standard_normal(size)


def relative_error(tangent: np.ndarray, central: np.ndarray) -> float:
    """|A v - fd| / |fd|."""
    return float(np.linalg.norm(tangent - central) / np.linalg.norm(central))


@pytest.mark.parametrize("element", ["TotalLagrangianElement2D4N", "UpdatedLagrangianElement2D4N"])
def test_hyperelastic_plate_tangent_matches_central_differences(element: str) -> None:
    model = ca.Model()
    mp = _plate(model, "HyperElasticPlaneStrain2DLaw", element)
    _clamp_and_pull(mp, 0.3)
    strategy = _newton(mp, max_iteration=1)
    assert not strategy.Solve()  # one iteration: a state away from equilibrium
    before = {node.Id: np.array(node.GetSolutionStepValue(ca.DISPLACEMENT)) for node in mp.Nodes}
    size = strategy.GetBuilderAndSolver().GetEquationSystemSize()
    tangent, central, direction = strategy.CheckTangentAlong(random_direction(size), 1e-6)
    fixed = [d.EquationId for d in strategy.GetBuilderAndSolver().GetDofSet() if d.IsFixed()]
    assert fixed and np.all(direction[fixed] == 0.0) and np.all(central[fixed] == 0.0)
    error = relative_error(tangent, central)
    print(f"hyperelastic plate ({element}): |Av - fd| / |fd| = {error:.2e}")
    assert error < 1e-8
    for node in mp.Nodes:  # the state is restored
        u = np.array(node.GetSolutionStepValue(ca.DISPLACEMENT))
        np.testing.assert_allclose(u, before[node.Id], rtol=0.0, atol=1e-15)
        assert node.X == pytest.approx(node.X0 + u[0], abs=1e-15)
    # The Newton correction as direction: A v is the RHS of the iterate.
    tangent, central, direction = strategy.CheckTangentAlong(None, 1e-6)
    assert np.linalg.norm(direction) > 0.0
    assert relative_error(tangent, central) < 1e-8


def test_check_refuses_a_wrong_size_and_a_step_that_is_not_positive() -> None:
    model = ca.Model()
    mp = _plate(model, "HyperElasticPlaneStrain2DLaw")
    _clamp_and_pull(mp, 0.1)
    strategy = _newton(mp, max_iteration=1)
    strategy.Solve()
    size = strategy.GetBuilderAndSolver().GetEquationSystemSize()
    with pytest.raises(ca.InputError, match=f"the direction has 3 entries, the system {size}"):
        strategy.CheckTangentAlong(np.ones(3), 1e-6)
    with pytest.raises(ca.InputError, match="the step h must be positive"):
        strategy.CheckTangentAlong(np.ones(size), 0.0)
