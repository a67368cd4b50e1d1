"""ProjectParameters blocks of the contact cases the tests write (a "Structure" of two bodies).

Imported by the tests as ``contact_cases`` (pytest puts this folder on ``sys.path``).
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path
from typing import Any, TypeVar

from process_descriptors import core_process, hold_displacement

import contact_app as ca
from contact_app.analysis import StructuralMechanicsAnalysis
from contact_app.analysis.reporting import Reporter
from contact_app.parameters import Parameters

AnalysisT = TypeVar("AnalysisT", bound=StructuralMechanicsAnalysis)

CONTACT_APPLICATION = "KratosMultiphysics.ContactStructuralMechanicsApplication"


def roller(part: str, axes: tuple[int, ...]) -> dict[str, Any]:
    """Return the process that holds the displacement of ``part`` at 0 along ``axes``."""
    constrained = [axis in axes for axis in range(3)]
    return hold_displacement(part, constrained, [0.0 if fixed else None for fixed in constrained])


def top_load(variable: str, modulus: float, direction: list[float]) -> dict[str, Any]:
    """Return the load on the conditions of ``Structure.Top_Load`` for the whole run."""
    return core_process(
        "assign_vector_by_direction_to_condition_process",
        {
            "model_part_name": "Structure.Top_Load",
            "variable_name": variable,
            "modulus": modulus,
            "direction": direction,
            "interval": [0.0, "End"],
        },
    )


def contact_process(module: str, contact_type: str, **extra: Any) -> dict[str, Any]:
    """Return a contact process between ``Contact_Slave`` and ``Contact_Master``."""
    return {
        "python_module": module,
        "kratos_module": CONTACT_APPLICATION,
        "Parameters": {
            "model_part_name": "Structure",
            "contact_model_part": {"0": ["Contact_Slave", "Contact_Master"]},
            "assume_master_slave": {"0": ["Contact_Slave"]},
            "contact_type": contact_type,
            **extra,
        },
    }


def problem_data(name: str, end_time: float) -> dict[str, Any]:
    """Return the ``problem_data`` of a quiet run from t = 0."""
    return {
        "problem_name": name,
        "parallel_type": "OpenMP",
        "start_time": 0.0,
        "end_time": end_time,
        "echo_level": 0,
    }


def static_contact_solver(
    directory: Path, mesh_name: str, domain_size: int, mortar_type: str, **extra: Any
) -> dict[str, Any]:
    """Return the static non-linear contact ``solver_settings`` of the mesh in ``directory``."""
    return {
        "model_part_name": "Structure",
        "domain_size": domain_size,
        "solver_type": "Static",
        "echo_level": 0,
        "analysis_type": "non_linear",
        "model_import_settings": {
            "input_type": "mdpa",
            "input_filename": str(directory / mesh_name),
        },
        "material_import_settings": {"materials_filename": str(directory / "materials.json")},
        "contact_settings": {"mortar_type": mortar_type},
        "time_stepping": {"time_step": 1.0},
        "convergence_criterion": "contact_residual_criterion",
        **extra,
    }


def copied_case_parameters(source: Path, directory: Path, end_time: float) -> dict[str, Any]:
    """Copy the case folder ``source`` to ``directory``; its ProjectParameters, shortened.

    The returned parameters end at ``end_time`` and write no output.
    """
    shutil.copytree(source, directory)
    parameters = json.loads((directory / "ProjectParameters.json").read_text())
    parameters["problem_data"]["end_time"] = end_time
    parameters["output_processes"] = {}
    return parameters


def run_quietly(
    analysis_type: type[AnalysisT], parameters: dict[str, Any], base_dir: Path
) -> AnalysisT:
    """Run ``analysis_type`` on ``parameters`` (files relative to ``base_dir``), nothing printed."""
    analysis = analysis_type(
        ca.Model(),
        Parameters(json.dumps(parameters)),
        base_dir=base_dir,
        reporter=Reporter(quiet=True),
    )
    analysis.Run()
    return analysis
