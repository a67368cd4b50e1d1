"""The solver mortar types read from the C++ condition table (docs/registered_conditions.md §4)."""

from __future__ import annotations

import pytest

import contact_app as ca
from contact_app import _core
from contact_app.contact.auxiliary_methods_solvers import check_mortar_type
from contact_app.parameters import Parameters

PAIRS = ("2D2N", "3D3N", "3D4N", "3D3N4N", "3D4N3N")


@pytest.mark.parametrize("mortar", _core.MortarTypes(), ids=lambda t: t.name)
def test_mortar_type_condition_names_are_registered(mortar: _core.MortarType) -> None:
    registered = set(ca.registered_conditions())
    for nv in (False, True) if mortar.method else (False,):
        for pair in PAIRS:
            assert f"{mortar.ConditionName(nv, False)}Condition{pair}" in registered
        if mortar.has_axisym:
            assert f"{mortar.ConditionName(nv, True)}Condition2D2N" in registered


@pytest.mark.parametrize("mortar", _core.MortarTypes(), ids=lambda t: t.name)
def test_mortar_type_dofs_are_among_its_nodal_variables(mortar: _core.MortarType) -> None:
    names = {v.Name() for v in mortar.nodal_variables}
    assert {"NORMAL", "NODAL_H"} <= names
    for dof, reaction in mortar.dofs:
        assert dof.Name().removesuffix("_X").removesuffix("_Y").removesuffix("_Z") in names
        assert reaction.Name().removesuffix("_X").removesuffix("_Y").removesuffix("_Z") in names
    assert (mortar.multiplier is None) == (not mortar.dofs)
    assert ("WEIGHTED_SLIP" in names) == mortar.frictional


def test_unknown_mortar_type_names_value_key_and_the_table() -> None:
    contact = Parameters({"mortar_type": "ALMContactFrictionles"})
    with pytest.raises(ca.InputError) as raised:
        check_mortar_type(contact)
    message = str(raised.value)
    assert 'unknown mortar_type "ALMContactFrictionles"' in message
    assert "mortar_type" in message.split("where:")[1]
    for mortar in _core.MortarTypes():
        assert f'"{mortar.name}"' in message
    assert 'did you mean "ALMContactFrictionless"' in message
