"""Model-part names as users write them: full dotted paths or the bare names of old Kratos files."""

from __future__ import annotations

from ._core import InputError, Model, ModelPart
from .parameters import suggest


def _all_parts(part: ModelPart) -> list[ModelPart]:
    parts = [part]
    for child in part.SubModelParts:
        parts.extend(_all_parts(child))
    return parts


def get_model_part(model: Model, name: str, where: str = "") -> ModelPart:
    """Return the model part called ``name``.

    A full dotted path ("Structure.Contact_Part") is tried first; otherwise a bare sub-model-part
    name is searched in every root ("Contact_Part" as old Kratos files write it), and must match
    exactly one part.

    Args:
        model: the model holding the root model parts.
        name: dotted path or bare name.
        where: location of the name in the settings, for messages ("ProjectParameters.json › ...").

    Raises:
        InputError: no part or several parts have that name.
    """
    if model.HasModelPart(name):
        return model.GetModelPart(name)
    matches: list[ModelPart] = []
    every_name: list[str] = []
    for root_name in model.GetModelPartNames():
        for part in _all_parts(model.GetModelPart(root_name)):
            every_name.append(part.FullName())
            if part.Name == name or part.FullName().endswith("." + name):
                matches.append(part)
    location = f"\n  where:    {where}" if where else ""
    if len(matches) == 1:
        return matches[0]
    if len(matches) > 1:
        listing = ", ".join(f'"{p.FullName()}"' for p in matches)
        raise InputError(
            f'model part name "{name}" is ambiguous{location}\n  matches:  {listing}\n'
            "  fix:      write the full dotted path"
        )
    hint = suggest(name, every_name + [n.rsplit(".", 1)[-1] for n in every_name])
    existing = ", ".join(f'"{n}"' for n in every_name[:15]) + (
        ", ..." if len(every_name) > 15 else ""
    )
    raise InputError(
        f'no model part "{name}"{location}\n  expected: one of {existing or "(no model parts yet)"}'
        + (f"\n  fix:      {hint}" if hint else "")
    )
