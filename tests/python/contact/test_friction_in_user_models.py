"""Friction in a user's model of the reference's example collection (2D press fit, ALM frictional).

The model gives mu only in the contact process ("friction_coefficients"), and its interface
conditions carry properties of their own without FRICTION_COEFFICIENT. mu used to be averaged from
those properties (0, with a warning) and the setting was ignored: mu = 0.1 and 0.5 gave
bit-identical runs. Here the first 20 steps (t = 0.02) run with each value.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from contact_cases import copied_case_parameters, run_quietly

import contact_app as ca
from contact_app.analysis import StructuralMechanicsAnalysis

PRESS_FIT = (
    Path(__file__).resolve().parents[3].parent / "shared/kratos_examples/press_fit/source/2D"
)

pytestmark = pytest.mark.skipif(not PRESS_FIT.is_dir(), reason="../shared/kratos_examples missing")


def _run(directory: Path, mu: float) -> StructuralMechanicsAnalysis:
    parameters = copied_case_parameters(PRESS_FIT, directory, 0.02)
    parameters["processes"]["contact_process_list"][0]["Parameters"]["friction_coefficients"] = {
        "0": mu
    }
    return run_quietly(StructuralMechanicsAnalysis, parameters, directory)


def test_press_fit_uses_the_friction_coefficient_of_its_contact_process(tmp_path: Path) -> None:
    runs = {mu: _run(tmp_path / str(mu), mu) for mu in (0.1, 0.5)}
    tangential = {}
    for mu, analysis in runs.items():
        assert all(step.converged for step in analysis.reporter.steps)
        slave = [
            node
            for node in analysis.model.GetModelPart("Structure.Contact").Nodes
            if node.Is(ca.SLAVE)
        ]
        assert slave and all(node.GetValue(ca.FRICTION_COEFFICIENT) == mu for node in slave)
        active = [node for node in slave if node.Is(ca.ACTIVE)]
        assert active
        for node in active:  # slipping nodes are on the Coulomb cone of their own mu
            if node.Is(ca.SLIP):
                traction = node.GetValue(ca.AUGMENTED_TANGENT_CONTACT_PRESSURE)
                normal = node.GetValue(ca.AUGMENTED_NORMAL_CONTACT_PRESSURE)
                assert (traction[0] ** 2 + traction[1] ** 2) ** 0.5 == pytest.approx(
                    mu * abs(normal), rel=1.0e-9
                )
        tangential[mu] = sum(
            abs(node.GetValue(ca.AUGMENTED_TANGENT_CONTACT_PRESSURE_X))
            + abs(node.GetValue(ca.AUGMENTED_TANGENT_CONTACT_PRESSURE_Y))
            for node in active
        )
    # Measured 4.08e6 and 3.56e7: the friction follows the setting (it was 0 for both).
    print(f"sum of |tangential traction| on the active nodes: {tangential}")
    assert tangential[0.5] > 1.5 * tangential[0.1] > 0.0
