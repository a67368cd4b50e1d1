"""Flags: named flags as module attributes, tri-state semantics, inheritance by kernel classes."""

from __future__ import annotations

import pytest

import contact_app as ca


def test_flags_every_registered_flag_is_exported() -> None:
    names = ca.registered_flags()
    assert {"ACTIVE", "SLIP", "SLAVE", "MASTER", "ISOLATED", "CONTACT"} <= set(names)
    for name in names:
        assert isinstance(getattr(ca, name), ca.Flags)
        assert name in ca.__all__
        assert ca.get_flag(name) == getattr(ca, name)


def test_flags_named_flags_are_distinct() -> None:
    flags = [getattr(ca, name) for name in ca.registered_flags()]
    assert len(set(flags)) == len(flags)


def test_flags_set_reset_are_tri_state() -> None:
    flags = ca.Flags()
    assert not flags.IsDefined(ca.ACTIVE)
    assert not flags.Is(ca.ACTIVE)
    flags.Set(ca.ACTIVE)
    assert flags.Is(ca.ACTIVE) and flags.IsDefined(ca.ACTIVE)
    flags.Set(ca.ACTIVE, False)
    assert flags.IsNot(ca.ACTIVE) and flags.IsDefined(ca.ACTIVE)
    assert flags.Is(ca.ACTIVE.AsFalse())
    flags.Reset(ca.ACTIVE)
    assert not flags.IsDefined(ca.ACTIVE)


def test_flags_or_combines_bits() -> None:
    combined = ca.ACTIVE | ca.SLIP
    flags = ca.Flags()
    flags.Set(combined)
    assert flags.Is(ca.ACTIVE) and flags.Is(ca.SLIP) and flags.IsNot(ca.SLAVE)
    assert repr(ca.ACTIVE | ca.SLIP.AsFalse()) == "Flags(ACTIVE, SLIP=False)"


def test_flags_equality_compares_bits() -> None:
    assert ca.ACTIVE == ca.get_flag("ACTIVE")
    assert ca.ACTIVE != ca.SLIP
    assert ca.ACTIVE != ca.ACTIVE.AsFalse()


def test_get_flag_unknown_name_raises_key_error_with_suggestion() -> None:
    with pytest.raises(KeyError, match='did you mean "ACTIVE"'):
        ca.get_flag("ACTIVEE")


def _owners() -> dict[str, object]:
    model_part = ca.Model().CreateModelPart("Flags")
    for node_id, x in ((1, 0.0), (2, 1.0)):
        model_part.CreateNewNode(node_id, x, 0.0, 0.0)
    properties = model_part.CreateNewProperties(1)
    return {
        "node": model_part.GetNode(1),
        "element": model_part.CreateNewElement("Element2D2N", 1, [1, 2], properties),
        "condition": model_part.CreateNewCondition("LineCondition2D2N", 1, [1, 2], properties),
        "process_info": model_part.ProcessInfo,
        "model_part": model_part,
    }


@pytest.mark.parametrize("owner", ["node", "element", "condition", "process_info", "model_part"])
def test_flags_are_inherited_by_kernel_classes(owner: str) -> None:
    obj = _owners()[owner]
    assert isinstance(obj, ca.Flags)
    obj.Set(ca.ACTIVE)
    obj.Set(ca.SLIP, False)
    assert obj.Is(ca.ACTIVE)
    assert obj.IsNot(ca.SLIP) and obj.IsDefined(ca.SLIP)
    assert not obj.IsDefined(ca.SLAVE)
    # Setting flags must not touch the rest of the object (Flags is not at offset 0 in entities).
    assert repr(obj)
