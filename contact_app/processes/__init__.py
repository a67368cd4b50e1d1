"""Core Kratos processes (``"kratos_module": "KratosMultiphysics"``).

One module per ``python_module`` name, each with ``Factory(settings, model)``:
``assign_scalar_variable_process``, ``assign_vector_variable_process``,
``assign_vector_by_direction_process``, ``assign_scalar_variable_to_conditions_process``,
``assign_vector_variable_to_conditions_process``,
``assign_vector_by_direction_to_condition_process``,
``fix_scalar_variable_process``, ``fix_vector_variable_process``,
``from_json_check_result_process``, ``json_output_process``, ``vtk_output_process``. Building
blocks: ``process`` (``Process``, ``OutputProcess``), ``interval`` and ``function_expression``.
"""

from __future__ import annotations

from .process import OutputProcess, Process

__all__ = ["OutputProcess", "Process"]
