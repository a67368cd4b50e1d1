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
def ComputePenaltyFrictionalActiveSet(model_part: contact_app._core.ModelPart, pure_slip: bool = False) -> typing.Annotated[list[int], "FixedSize(2)"]:
    """
    [ACTIVE flips, SLIP flips].
    """
def ComputePenaltyFrictionlessActiveSet(model_part: contact_app._core.ModelPart) -> int:
    """
    Number of ACTIVE flips.
    """
