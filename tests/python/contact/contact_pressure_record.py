"""The per-step record of the contact pressure field, for contact_app and for the Kratos oracle.

Plain Python over a Kratos-like API: ``scripts/oracle/cylinders_pressure.py`` passes
``KratosMultiphysics`` and the contact application's AUGMENTED_NORMAL_CONTACT_PRESSURE, the tests
pass ``contact_app``, and both record the same numbers the same way.
"""

from __future__ import annotations

import statistics
from typing import Any


def step_record(main: Any, api: Any, augmented_pressure: Any, fixed_part: str) -> dict:
    """The contact state of the step just finished.

    Over the ACTIVE slave nodes of ``main``'s Contact part: their number, the largest |pressure|
    (and its node), the median |pressure|, the smallest and the median NODAL_AREA; and the
    REACTION summed over the sub model part ``fixed_part``.
    """
    rows = [
        (node.Id, abs(node.GetValue(augmented_pressure)), node.GetValue(api.NODAL_AREA))
        for node in main.GetSubModelPart("Contact").Nodes
        if node.Is(api.SLAVE) and node.Is(api.ACTIVE)
    ]
    fixed = main.GetSubModelPart(fixed_part)
    record = {
        "step": main.ProcessInfo[api.STEP],
        "time": main.ProcessInfo[api.TIME],
        "active": len(rows),
        "base_reaction": [
            float(sum(node.GetSolutionStepValue(variable) for node in fixed.Nodes))
            for variable in (api.REACTION_X, api.REACTION_Y, api.REACTION_Z)
        ],
    }
    if rows:
        largest = max(rows, key=lambda row: row[1])
        record.update(
            max_pressure=largest[1],
            max_pressure_node=largest[0],
            median_pressure=statistics.median(row[1] for row in rows),
            min_nodal_area=min(row[2] for row in rows),
            median_nodal_area=statistics.median(row[2] for row in rows),
        )
    return record
