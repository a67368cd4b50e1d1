"""Properties, ProcessInfo and tables: typed values, items and flags."""

from __future__ import annotations

import numpy as np
import pytest

import contact_app as ca


def test_properties_values_of_every_kind(structure: ca.ModelPart) -> None:
    properties = structure.CreateNewProperties(3)
    properties.SetValue(ca.YOUNG_MODULUS, 2.1e11)
    properties[ca.POISSON_RATIO] = 0.3
    properties[ca.INTEGRATION_ORDER] = 3
    properties[ca.COMPUTE_LUMPED_MASS_MATRIX] = True
    properties[ca.TYING_VARIABLE] = "DISPLACEMENT"
    properties[ca.VOLUME_ACCELERATION] = (0.0, -9.81, 0.0)
    properties[ca.INITIAL_STRAIN_VECTOR] = [1.0, 2.0, 3.0]
    properties[ca.CONSTITUTIVE_MATRIX] = np.arange(4.0).reshape(2, 2)
    assert properties.Id == 3
    assert properties.GetValue(ca.YOUNG_MODULUS) == 2.1e11
    assert properties[ca.POISSON_RATIO] == 0.3
    assert properties[ca.INTEGRATION_ORDER] == 3
    assert properties[ca.COMPUTE_LUMPED_MASS_MATRIX] is True
    assert properties[ca.TYING_VARIABLE] == "DISPLACEMENT"
    assert properties[ca.VOLUME_ACCELERATION_Y] == pytest.approx(-9.81)
    np.testing.assert_array_equal(properties[ca.INITIAL_STRAIN_VECTOR], [1.0, 2.0, 3.0])
    np.testing.assert_array_equal(properties[ca.CONSTITUTIVE_MATRIX], [[0.0, 1.0], [2.0, 3.0]])
    assert properties.Has(ca.YOUNG_MODULUS) and ca.POISSON_RATIO in properties
    assert not properties.Has(ca.DENSITY)
    assert structure.GetProperties(3) == properties


def test_properties_wrong_value_type_raises_type_error(structure: ca.ModelPart) -> None:
    properties = structure.CreateNewProperties(1)
    with pytest.raises(TypeError):
        properties[ca.INTEGRATION_ORDER] = "two"
    with pytest.raises(TypeError):
        properties[ca.TYING_VARIABLE] = 2.0


def test_properties_hold_a_constitutive_law_and_refuse_other_pointers(
    structure: ca.ModelPart,
) -> None:
    properties = structure.CreateNewProperties(1)
    assert not properties.Has(ca.CONSTITUTIVE_LAW)
    assert properties.GetValue(ca.CONSTITUTIVE_LAW) is None
    properties[ca.CONSTITUTIVE_LAW] = ca.create_constitutive_law("LinearElastic3DLaw")
    assert properties.Has(ca.CONSTITUTIVE_LAW)
    assert properties[ca.CONSTITUTIVE_LAW].GetStrainSize() == 6
    with pytest.raises(ca.InputError, match="INDEX_MAP of type Pointer .* cannot be read"):
        properties.GetValue(ca.INDEX_MAP)
    with pytest.raises(ca.InputError, match=r"holds a C\+\+ object"):
        properties[ca.INDEX_MAP]


def test_get_properties_creates_missing_ones_like_kratos(structure: ca.ModelPart) -> None:
    assert not structure.HasProperties(7)
    assert structure.GetProperties(7).Id == 7
    assert structure.HasProperties(7) and structure.NumberOfProperties() == 1
    assert [properties.Id for properties in structure.Properties] == [7]


def test_properties_tables_interpolate(structure: ca.ModelPart) -> None:
    table = ca.Table()
    table.AddRow(0.0, 0.0)
    table.AddRow(1.0, 10.0)
    assert table.GetValue(0.25) == pytest.approx(2.5)
    assert table.GetDerivative(0.5) == pytest.approx(10.0)
    assert len(table) == 2 and table.Data() == [(0.0, 0.0), (1.0, 10.0)]
    properties = structure.CreateNewProperties(1)
    properties.SetTable(ca.TEMPERATURE, ca.YOUNG_MODULUS, table)
    assert properties.HasTable(ca.TEMPERATURE, ca.YOUNG_MODULUS)
    assert properties.GetTable(ca.TEMPERATURE, ca.YOUNG_MODULUS).GetValue(0.5) == pytest.approx(5.0)
    structure.AddTable(1, table)
    assert structure.NumberOfTables() == 1 and structure.GetTable(1).GetValue(1.0) == 10.0


def test_process_info_values_and_flags(structure: ca.ModelPart) -> None:
    info = structure.ProcessInfo
    info[ca.DELTA_TIME] = 0.1
    info.SetValue(ca.STEP, 4)
    info[ca.ACTIVE_SET_COMPUTED] = True
    assert (
        info[ca.DELTA_TIME] == 0.1
        and info.GetValue(ca.STEP) == 4
        and info[ca.ACTIVE_SET_COMPUTED] is True
    )
    assert info.Has(ca.DELTA_TIME) and not info.Has(ca.TIME)
    info.Set(ca.ACTIVE)
    assert info.Is(ca.ACTIVE) and not info.IsDefined(ca.SLIP)
    # One ProcessInfo per hierarchy: a sub model part sees the same values and flags.
    contact = structure.CreateSubModelPart("Contact")
    assert contact.ProcessInfo[ca.STEP] == 4 and contact.ProcessInfo.Is(ca.ACTIVE)
    assert contact.ProcessInfo == info
