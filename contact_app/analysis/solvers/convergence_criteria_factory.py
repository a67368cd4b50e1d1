"""Standard structural convergence criteria by name (Kratos ``convergence_criteria_factory``).

| ``convergence_criterion`` | criterion |
|---|---|
| ``displacement_criterion`` | DisplacementCriteria(displacement_relative/absolute_tolerance) |
| ``residual_criterion`` | ResidualCriteria(residual_relative/absolute_tolerance) |
| ``and_criterion`` / ``or_criterion`` | And/Or(residual, displacement) |

The ``contact_*`` names belong to the contact solvers, which bring their own factory.
"""

from __future__ import annotations

from dataclasses import dataclass

import contact_app as ca

from ...parameters import Parameters, suggest
from ..validation import error, not_supported

STRUCTURAL_CRITERIA = (
    "displacement_criterion",
    "residual_criterion",
    "and_criterion",
    "or_criterion",
)
CONTACT_CRITERIA = (
    "contact_displacement_criterion",
    "contact_residual_criterion",
    "contact_mixed_criterion",
    "contact_and_criterion",
    "contact_or_criterion",
)


@dataclass
class ConvergenceCriterion:
    """A created criterion and its parts (the reporter reads the parts' last norms).

    Attributes:
        criterion: the object handed to the Newton strategy.
        residual: the residual part, if any.
        displacement: the displacement-increment part, if any.

    """

    criterion: ca.ConvergenceCriteria
    residual: ca.ResidualCriteria | None = None
    displacement: ca.DisplacementCriteria | None = None


def check_criterion_name(settings: Parameters, known: tuple[str, ...] = STRUCTURAL_CRITERIA) -> str:
    """Validate ``settings["convergence_criterion"]``.

    Raises:
        ConfigurationError: a contact criterion name without contact settings.
        InputError: an unknown name (with a did-you-mean).

    """
    name = settings["convergence_criterion"].GetString()
    if name in known:
        return name
    if name in CONTACT_CRITERIA:
        raise not_supported(
            settings,
            "convergence_criterion",
            f'the contact convergence criterion "{name}" without contact solver',
            'contact criteria are available with "contact_settings" (contact solvers); '
            f"for a structural problem use one of {', '.join(STRUCTURAL_CRITERIA)}",
        )
    raise error(
        settings,
        "convergence_criterion",
        f'unknown convergence criterion "{name}"',
        "one of " + ", ".join(f'"{n}"' for n in known),
        suggest(name, list(known) + list(CONTACT_CRITERIA)),
    )


def CreateConvergenceCriterion(settings: Parameters) -> ConvergenceCriterion:
    """Create the criterion named by ``settings["convergence_criterion"]``.

    Args:
        settings: solver settings with ``convergence_criterion``, ``echo_level`` and the
            ``displacement_*``/``residual_*`` tolerances (defaults already assigned).

    Returns:
        The criterion with its residual and displacement parts.

    """
    name = check_criterion_name(settings)
    echo_level = settings["echo_level"].GetInt()
    residual = ca.ResidualCriteria(
        settings["residual_relative_tolerance"].GetDouble(),
        settings["residual_absolute_tolerance"].GetDouble(),
    )
    displacement = ca.DisplacementCriteria(
        settings["displacement_relative_tolerance"].GetDouble(),
        settings["displacement_absolute_tolerance"].GetDouble(),
    )
    for part in (residual, displacement):
        part.SetEchoLevel(echo_level)
    if name == "residual_criterion":
        return ConvergenceCriterion(residual, residual=residual)
    if name == "displacement_criterion":
        return ConvergenceCriterion(displacement, displacement=displacement)
    combine = ca.AndCriteria if name == "and_criterion" else ca.OrCriteria
    combined = combine(residual, displacement)
    combined.SetEchoLevel(echo_level)
    return ConvergenceCriterion(combined, residual=residual, displacement=displacement)
