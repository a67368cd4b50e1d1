"""The allowed range of every numeric settings key, by key name (one table for all schemas).

:meth:`contact_app.parameters.Parameters.ValidateAndAssignDefaults` applies it to every number a
user writes, so a key gets the same check in every block that uses it (``max_iteration`` of the
solver and of the linear solver, the ``*_tolerance`` keys of every criterion, ...). Numbers of keys
not listed here only have to be finite (loads, coordinates and offsets may have any sign).
"""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(frozen=True)
class Range:
    """An interval of allowed values; ``low_open``/``high_open`` exclude the bound."""

    low: float = -math.inf
    high: float = math.inf
    low_open: bool = False
    high_open: bool = False
    meaning: str = ""

    def contains(self, value: float) -> bool:
        """Tell whether ``value`` lies in the interval."""
        above = value > self.low if self.low_open else value >= self.low
        below = value < self.high if self.high_open else value <= self.high
        return above and below

    def text(self) -> str:
        """``"a number > 0"``, ``"a number in [-1, 0]"``, ..."""
        if math.isinf(self.high):
            return f"a number {'>' if self.low_open else '≥'} {self.low:g}"
        if math.isinf(self.low):
            return f"a number {'<' if self.high_open else '≤'} {self.high:g}"
        left, right = "(" if self.low_open else "[", ")" if self.high_open else "]"
        return f"a number in {left}{self.low:g}, {self.high:g}{right}"


_POSITIVE = Range(0.0, low_open=True)
_NON_NEGATIVE = Range(0.0)
_AT_LEAST_ONE = Range(1.0)

#: Key name -> allowed range (the meaning is added to the message).
RANGES: dict[str, Range] = {
    # time stepping and output frequencies
    "time_step": Range(0.0, low_open=True, meaning="the time step"),
    "time_frequency": Range(0.0, meaning="the time between two outputs or checks"),
    "output_interval": Range(0.0, meaning="the interval between two outputs"),
    # counts
    "echo_level": _NON_NEGATIVE,
    "verbosity": _NON_NEGATIVE,
    "buffer_size": _AT_LEAST_ONE,
    "max_iteration": _AT_LEAST_ONE,
    "max_iteration_number": _AT_LEAST_ONE,
    "max_number_splits": _AT_LEAST_ONE,
    "inner_loop_iterations": _AT_LEAST_ONE,
    "max_line_search_iterations": _AT_LEAST_ONE,
    "gmres_krylov_space_dimension": _AT_LEAST_ONE,
    "block_size": _AT_LEAST_ONE,
    "coarse_enough": _AT_LEAST_ONE,
    "pre_sweeps": _NON_NEGATIVE,
    "post_sweeps": _NON_NEGATIVE,
    "bucket_size": _AT_LEAST_ONE,
    "max_number_results": _AT_LEAST_ONE,
    "database_step_update": _AT_LEAST_ONE,
    "slip_step_reset_frequency": _NON_NEGATIVE,
    "integration_order": Range(1.0, 5.0, meaning="a Gauss rule order"),
    "output_precision": _NON_NEGATIVE,
    "properties_id": _NON_NEGATIVE,
    "mesh_id": _NON_NEGATIVE,
    "skiprows": _NON_NEGATIVE,
    "first_column_id": _NON_NEGATIVE,
    "second_column_id": _NON_NEGATIVE,
    # step cutting
    "split_factor": Range(1.0, low_open=True, meaning="the factor a failed step is divided by"),
    # time integration
    "newmark_beta": Range(0.0, 0.5, low_open=True, meaning="the Newmark β"),
    "damp_factor_m": Range(-1.0, 0.0, meaning="the Bossak α_m"),
    "rayleigh_alpha": _NON_NEGATIVE,
    "rayleigh_beta": _NON_NEGATIVE,
    # line search
    "first_alpha_value": _POSITIVE,
    "second_alpha_value": _POSITIVE,
    "min_alpha": _POSITIVE,
    "max_alpha": _POSITIVE,
    # contact: penalties, scale factors and thresholds
    "penalty": Range(0.0, meaning="the contact penalty (0: computed)"),
    "scale_factor": Range(0.0, low_open=True, meaning="the multiplier scale factor"),
    "penalty_scale_factor": _POSITIVE,
    "stiffness_factor": _POSITIVE,
    "tangent_factor": _POSITIVE,
    "max_gap_factor": _NON_NEGATIVE,
    "search_factor": _POSITIVE,
    "active_check_factor": _POSITIVE,
    "bounding_box_factor": _POSITIVE,
    "zero_tolerance_factor": _POSITIVE,
    "reaction_check_stiffness_factor": _POSITIVE,
    "automatic_gap_factor": _NON_NEGATIVE,
    "normal_check_proportion": _POSITIVE,
    "normal_orientation_threshold": Range(-1.0, 1.0, meaning="a cosine"),
    "operator_threshold": _NON_NEGATIVE,
    "slip_threshold": _NON_NEGATIVE,
    "slip_augmentation_coefficient": _NON_NEGATIVE,
    "ratio_normal_tangent_threshold": _NON_NEGATIVE,
    "max_gap_threshold": _NON_NEGATIVE,
    "lower_bounding_box_coefficient": _NON_NEGATIVE,
    "higher_bounding_box_coefficient": _NON_NEGATIVE,
    "logistic_exponent_factor": _POSITIVE,
}

#: Ranges of every entry of an object, by the object's key (``"friction_coefficients": {"0": μ}``).
ENTRY_RANGES: dict[str, Range] = {
    "friction_coefficients": Range(0.0, meaning="a Coulomb friction coefficient μ"),
}


def range_of(key: str, parent: str | None) -> Range | None:
    """Return the range of ``key`` (inside the object named ``parent``), or None."""
    if parent is not None and parent in ENTRY_RANGES:
        return ENTRY_RANGES[parent]
    if key in RANGES:
        return RANGES[key]
    if key.endswith("tolerance"):
        return Range(0.0, meaning="a tolerance")
    return None
