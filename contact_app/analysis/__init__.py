"""Kratos-style analysis driver: analysis stage, structural solvers, materials, processes, report.

``run(path_or_dict)`` runs a ``ProjectParameters.json`` (Kratos files run unchanged) and returns the
analysis; ``StructuralMechanicsAnalysis(model, parameters)`` is the Kratos-style stage with
``Run()``, ``Initialize()``, ``RunSolutionLoop()`` and ``Finalize()``.
"""

from .analysis_stage import AnalysisStage
from .materials import MaterialsReader, ReadMaterials
from .paths import PathResolver
from .process_factory import KratosProcessFactory
from .reporting import IterationStatus, Reporter, StepRecord
from .solvers import (
    CreateSolver,
    CreateSolverByParameters,
    ImplicitMechanicalSolver,
    MechanicalSolver,
    StaticMechanicalSolver,
)
from .structural_mechanics_analysis import (
    StructuralMechanicsAnalysis,
    ValidateProjectParameters,
    run,
)

__all__ = [
    "AnalysisStage",
    "CreateSolver",
    "CreateSolverByParameters",
    "ImplicitMechanicalSolver",
    "KratosProcessFactory",
    "MaterialsReader",
    "MechanicalSolver",
    "PathResolver",
    "ReadMaterials",
    "IterationStatus",
    "Reporter",
    "StaticMechanicalSolver",
    "StepRecord",
    "StructuralMechanicsAnalysis",
    "ValidateProjectParameters",
    "run",
]
