"""Variables: module attributes, classes, registry lookup and comparison."""

from __future__ import annotations

import pytest

import contact_app as ca


@pytest.mark.parametrize(
    ("name", "cls", "type_name"),
    [
        ("DISPLACEMENT", ca.Array1DVariable3, "Array"),
        ("DISPLACEMENT_X", ca.DoubleVariable, "Component"),
        ("YOUNG_MODULUS", ca.DoubleVariable, "Double"),
        ("WEIGHTED_GAP", ca.DoubleVariable, "Double"),
        ("STEP", ca.IntegerVariable, "Integer"),
        ("IS_RESTARTED", ca.BoolVariable, "Bool"),
        ("CAUCHY_STRESS_VECTOR", ca.VectorVariable, "Vector"),
        ("CONSTITUTIVE_MATRIX", ca.MatrixVariable, "Matrix"),
        ("TYING_VARIABLE", ca.StringVariable, "String"),
        ("CONSTITUTIVE_LAW", ca.ConstitutiveLawVariable, "Pointer"),
        ("INDEX_MAP", ca.VariableData, "Pointer"),
    ],
)
def test_variable_attribute_has_its_class_and_type(name: str, cls: type, type_name: str) -> None:
    variable = getattr(ca, name)
    assert type(variable) is cls
    assert isinstance(variable, ca.VariableData)
    assert variable.Name() == name
    assert variable.Type() == type_name


def test_variables_every_registered_name_is_exported() -> None:
    names = ca.registered_variables()
    assert names == sorted(names)
    assert {"DISPLACEMENT", "WEIGHTED_GAP", "TYING_VARIABLE", "PAIRED_NORMAL_Z"} <= set(names)
    for name in names:
        assert getattr(ca, name).Name() == name
        assert name in ca.__all__


def test_variables_keys_are_dense() -> None:
    keys = sorted(ca.get_variable(name).Key() for name in ca.registered_variables())
    assert keys == list(range(len(keys)))


def test_get_variable_returns_the_module_attribute() -> None:
    assert ca.get_variable("WEIGHTED_GAP") is ca.WEIGHTED_GAP
    assert ca.get_variable("DISPLACEMENT_X") == ca.DISPLACEMENT_X


def test_get_variable_unknown_name_raises_key_error_with_suggestion() -> None:
    with pytest.raises(
        KeyError, match='unknown variable "DISPLACEMNT".*did you mean "DISPLACEMENT"'
    ):
        ca.get_variable("DISPLACEMNT")


def test_component_variable_knows_its_source() -> None:
    assert ca.DISPLACEMENT_Y.IsComponent()
    assert ca.DISPLACEMENT_Y.GetSourceVariable() == ca.DISPLACEMENT
    assert ca.DISPLACEMENT_Y.GetComponentIndex() == 1
    assert not ca.DISPLACEMENT.IsComponent()
    assert ca.DISPLACEMENT.GetSourceVariable() is None


def test_variables_compare_and_hash_by_key() -> None:
    assert ca.DISPLACEMENT == ca.get_variable("DISPLACEMENT")
    assert ca.DISPLACEMENT != ca.REACTION
    assert ca.DISPLACEMENT != "DISPLACEMENT"
    lookup = {ca.DISPLACEMENT: "u", ca.REACTION: "r"}
    assert lookup[ca.get_variable("REACTION")] == "r"
    assert hash(ca.DISPLACEMENT) == ca.DISPLACEMENT.Key()


def test_variable_repr_names_class_and_variable() -> None:
    assert repr(ca.YOUNG_MODULUS) == "<DoubleVariable YOUNG_MODULUS>"
    assert repr(ca.NORMAL) == "<Array1DVariable3 NORMAL>"
    assert str(ca.NORMAL) == "NORMAL"


def test_variable_zero_values() -> None:
    assert ca.YOUNG_MODULUS.Zero() == 0.0
    assert list(ca.NORMAL.Zero()) == [0.0, 0.0, 0.0]
    assert ca.TYING_VARIABLE.Zero() == ""
    assert ca.IS_RESTARTED.Zero() is False
