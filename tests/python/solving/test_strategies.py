"""Structural solving from Python: strategies, schemes, builders, criteria and linear solvers."""

import numpy as np
import pytest
from structure_model_part import create_structure

import contact_app as ca


def _plate(
    model: ca.Model,
    law: str = "LinearElasticPlaneStress2DLaw",
    element: str = "SmallDisplacementElement2D4N",
) -> ca.ModelPart:
    """Build a 2 x 1 plate of 4 x 2 distorted bilinear quads (E = 200, nu = 0.3, t = 1)."""
    mp, props = create_structure(model, 2, 200.0, law, thickness=1.0)
    nx, ny = 4, 2
    for j in range(ny + 1):
        for i in range(nx + 1):
            # interior nodes shifted: the patch test must hold on distorted elements
            shift = 0.07 if 0 < i < nx and 0 < j < ny else 0.0
            mp.CreateNewNode(1 + i + j * (nx + 1), 2.0 * i / nx + shift, 1.0 * j / ny - shift, 0.0)
    element_id = 1
    for j in range(ny):
        for i in range(nx):
            n0 = 1 + i + j * (nx + 1)
            nodes = [n0, n0 + 1, n0 + 1 + nx + 1, n0 + nx + 1]
            mp.CreateNewElement(element, element_id, nodes, props)
            element_id += 1
    for node in mp.Nodes:
        node.AddDof(ca.DISPLACEMENT_X, ca.REACTION_X)
        node.AddDof(ca.DISPLACEMENT_Y, ca.REACTION_Y)
    return mp


def _clamp_and_pull(mp: ca.ModelPart, displacement: float) -> None:
    """Clamp the edge x = 0 and prescribe u_x = ``displacement`` on the edge x = 2."""
    for node in mp.Nodes:
        if node.X0 == 0.0:
            node.Fix(ca.DISPLACEMENT_X)
            node.Fix(ca.DISPLACEMENT_Y)
        if node.X0 == 2.0:
            node.Fix(ca.DISPLACEMENT_X)
            node.SetSolutionStepValue(ca.DISPLACEMENT_X, 0, displacement)


def _newton(
    mp: ca.ModelPart, builder: str = "block", max_iteration: int = 10
) -> ca.SolvingStrategy:
    solver = ca.CreateLinearSolver("skyline_lu_factorization")
    if builder == "block":
        builder_and_solver = ca.ResidualBasedBlockBuilderAndSolver(solver)
    else:
        builder_and_solver = ca.ResidualBasedEliminationBuilderAndSolver(solver)
    criterion = ca.OrCriteria(
        ca.ResidualCriteria(1e-10, 1e-14), ca.DisplacementCriteria(1e-10, 1e-14)
    )
    scheme = ca.ResidualBasedIncrementalUpdateStaticScheme()
    return ca.ResidualBasedNewtonRaphsonStrategy(
        mp, scheme, criterion, builder_and_solver, max_iteration=max_iteration
    )


@pytest.mark.parametrize("builder", ["block", "elimination"])
def test_strategy_uniaxial_patch_reproduces_uniform_stress(builder: str) -> None:
    model = ca.Model()
    mp = _plate(model)
    strain = 1.0e-3
    for node in mp.Nodes:
        if node.X0 == 0.0:
            node.Fix(ca.DISPLACEMENT_X)
        if node.X0 == 2.0:
            node.Fix(ca.DISPLACEMENT_X)
            node.SetSolutionStepValue(ca.DISPLACEMENT_X, 0, 2.0 * strain)
        if node.X0 == 0.0 and node.Y0 == 0.0:
            node.Fix(ca.DISPLACEMENT_Y)
    strategy = _newton(mp, builder)
    strategy.Check()
    assert strategy.Solve()
    for node in mp.Nodes:
        u = node.GetSolutionStepValue(ca.DISPLACEMENT)
        assert u[0] == pytest.approx(strain * node.X0, abs=1e-13)
        assert u[1] == pytest.approx(-0.3 * strain * node.Y0, abs=1e-13)
        assert node.X == pytest.approx(node.X0 + u[0], abs=1e-15)  # the mesh moved
    right = sum(n.GetSolutionStepValue(ca.REACTION_X) for n in mp.Nodes if n.X0 == 2.0)
    assert right == pytest.approx(200.0 * strain * 1.0, rel=1e-10)
    for element in mp.Elements:
        stresses = element.CalculateOnIntegrationPoints(ca.CAUCHY_STRESS_VECTOR, mp.ProcessInfo)
        for stress in stresses:
            np.testing.assert_allclose(stress, [0.2, 0.0, 0.0], atol=1e-12)


def test_strategy_reports_a_step_that_does_not_converge() -> None:
    model = ca.Model()
    mp = _plate(model, "HyperElasticPlaneStrain2DLaw")
    _clamp_and_pull(mp, 0.5)
    strategy = _newton(mp, max_iteration=1)
    assert not strategy.Solve()
    assert not strategy.IsConverged()
    assert strategy.GetIterationNumber() == 1
    assert len(strategy.IterationHistory()) == 1
    strategy.SetMaxIterationNumber(30)
    assert strategy.Solve()
    assert strategy.IsConverged()


def test_linear_solver_names_map_and_unknown_names_suggest() -> None:
    assert ca.ResolveLinearSolverName("SkylineLUFactorizationSolver") == "direct"
    assert ca.CreateLinearSolver("cholmod").Info() == "cholmod"
    assert "skyline_lu_factorization" in ca.registered_linear_solvers()
    with pytest.raises(ca.InputError, match='did you mean "bicgstab"'):
        ca.CreateLinearSolver("bicgstabb")


def test_unknown_constitutive_law_suggests_the_registered_name() -> None:
    with pytest.raises(ca.InputError, match='did you mean "LinearElastic3DLaw"'):
        ca.create_constitutive_law("LinearElastic3dLaw")
    assert "HyperElastic3DLaw" in ca.registered_constitutive_laws()
    assert "SmallDisplacementElement3D8N" in ca.registered_elements()
    assert "SurfaceLoadCondition3D4N" in ca.registered_conditions()


def test_bossak_scheme_checks_its_parameters() -> None:
    with pytest.raises(ca.InputError, match="damp_factor_m"):
        ca.ResidualBasedBossakDisplacementScheme(-0.8)
    assert ca.ResidualBasedNewmarkDisplacementScheme().Info() == "newmark"


def test_strategy_echo_prints_the_iterations(capfd: pytest.CaptureFixture[str]) -> None:
    model = ca.Model()
    mp = _plate(model)
    _clamp_and_pull(mp, 1.0e-3)
    strategy = _newton(mp)
    strategy.SetEchoLevel(2)
    assert strategy.Solve()
    output = capfd.readouterr().out
    assert "Newton iteration 1: res ratio" in output
    assert "Newton: converged in" in output
