"""The public package: exports, exception hierarchy and metadata."""

from __future__ import annotations

import pytest

import contact_app as ca


def test_package_all_lists_classes_functions_variables_and_flags() -> None:
    assert {"Model", "ModelPart", "Node", "ModelPartIO", "VariableUtils", "get_variable"} <= set(
        ca.__all__
    )
    assert {"DISPLACEMENT", "WEIGHTED_GAP", "ACTIVE", "SLIP"} <= set(ca.__all__)
    assert len(ca.__all__) == len(set(ca.__all__))
    for name in ca.__all__:
        assert hasattr(ca, name), name


def test_package_star_import_exports_variables() -> None:
    namespace: dict[str, object] = {}
    exec("from contact_app import *", namespace)
    assert namespace["DISPLACEMENT_X"] == ca.DISPLACEMENT_X and namespace["ACTIVE"] == ca.ACTIVE


def test_input_error_is_a_value_error() -> None:
    assert issubclass(ca.InputError, ValueError)
    with pytest.raises(ValueError, match="unknown element"):
        ca.Model().CreateModelPart("X").CreateNewElement("NoSuchElement", 1, [1], None)


@pytest.mark.parametrize(
    "error", ["InputError", "ConfigurationError", "ConvergenceError", "InternalError"]
)
def test_exceptions_are_public_exception_classes(error: str) -> None:
    cls = getattr(ca, error)
    assert issubclass(cls, Exception)
    assert cls.__module__ == "contact_app" and cls.__name__ == error


def _assert_every_pair_registered(names: set[str], family: str, nv_family: str) -> None:
    """``family`` and its normal-variation twin have a mortar contact condition of every pair."""
    for pair in ("2D2N", "3D3N", "3D4N", "3D3N4N", "3D4N3N"):
        assert f"{family}MortarContactCondition{pair}" in names
        assert f"{nv_family}MortarContactCondition{pair}" in names


def test_package_registers_the_alm_frictionless_contact_conditions() -> None:
    names = set(ca.registered_conditions())
    _assert_every_pair_registered(names, "ALMFrictionless", "ALMNVFrictionless")
    assert "ALMFrictionlessAxisymMortarContactCondition2D2N" in names
    assert "ALMNVFrictionlessAxisymMortarContactCondition2D2N" in names


def test_package_registers_the_alm_frictionless_components_contact_conditions() -> None:
    names = set(ca.registered_conditions())
    _assert_every_pair_registered(names, "ALMFrictionlessComponents", "ALMNVFrictionlessComponents")
    assert not any("FrictionlessComponentsAxisym" in name for name in names)
    assert sum("FrictionlessComponents" in name for name in names) == 10


def test_package_registers_the_penalty_frictionless_contact_conditions() -> None:
    names = set(ca.registered_conditions())
    _assert_every_pair_registered(names, "PenaltyFrictionless", "PenaltyNVFrictionless")
    assert "PenaltyFrictionlessAxisymMortarContactCondition2D2N" in names
    # All 68 documented contact names (58 contact families + 5 mesh tying + 5 MPC), the constraint.
    contact = [n for n in names if "MortarContactCondition" in n or n.startswith("MeshTying")]
    assert len(contact) == 68
    frictional = ("PenaltyFrictionalMortar", "PenaltyNVFrictionalMortar")
    assert sum(n.startswith(frictional) for n in names) == 10
    assert "ContactMasterSlaveConstraint" in ca.registered_constraints()
