"""Process descriptors of ProjectParameters.json that the tests and the oracle scripts write.

On ``sys.path`` for the tests through pytest's ``pythonpath`` (pyproject.toml); scripts/oracle
imports it from this folder. Plain Python, so that the Kratos environment can import it too.
"""

from __future__ import annotations

from typing import Any


def core_process(module: str, parameters: dict[str, Any]) -> dict[str, Any]:
    """Return the descriptor of a core (``KratosMultiphysics``) process."""
    return {
        "python_module": module,
        "kratos_module": "KratosMultiphysics",
        "Parameters": parameters,
    }


def hold_displacement(part: str, constrained: list[bool], value: list[Any], **extra: Any) -> dict:
    """Return an ``assign_vector_variable_process`` on DISPLACEMENT of ``Structure.<part>``."""
    return core_process(
        "assign_vector_variable_process",
        {
            "model_part_name": f"Structure.{part}",
            "variable_name": "DISPLACEMENT",
            "constrained": constrained,
            "value": value,
            **extra,
        },
    )
