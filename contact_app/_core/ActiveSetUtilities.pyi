"""
Semi-smooth Newton active-set and stick/slip updates.
"""
from __future__ import annotations
import contact_app._core
import typing
__all__: list[str] = ['ComputeALMFrictionalActiveSet', 'ComputeALMFrictionlessActiveSet', 'ComputeALMFrictionlessComponentsActiveSet', 'ComputePenaltyFrictionalActiveSet', 'ComputePenaltyFrictionlessActiveSet']
def ComputeALMFrictionalActiveSet(model_part: contact_app._core.ModelPart, pure_slip: bool = False) -> typing.Annotated[list[int], "FixedSize(2)"]:
    """
    [ACTIVE flips, SLIP flips].
    """
def ComputeALMFrictionlessActiveSet(model_part: contact_app._core.ModelPart) -> int:
    """
    Number of ACTIVE flips.
    """
def ComputeALMFrictionlessComponentsActiveSet(model_part: contact_app._core.ModelPart) -> int:
    """
    Number of ACTIVE flips.
    """
def ComputePenaltyFrictionalActiveSet(model_part: contact_app._core.ModelPart, pure_slip: bool = False, release_gap: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> typing.Annotated[list[int], "FixedSize(2)"]:
    """
    [ACTIVE flips and held open nodes, SLIP flips].
    """
def ComputePenaltyFrictionlessActiveSet(model_part: contact_app._core.ModelPart, release_gap: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> int:
    """
    Number of ACTIVE flips and held open nodes (release_gap: docs/theory/active_set.md section 2).
    """
