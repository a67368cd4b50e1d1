"""Structural solvers: the MechanicalSolver base, static and implicit dynamic, their selection."""

from .implicit_dynamic_solver import ImplicitMechanicalSolver
from .mechanical_solver import MechanicalSolver
from .solver_wrapper import CreateSolver, CreateSolverByParameters
from .static_solver import StaticMechanicalSolver

__all__ = [
    "CreateSolver",
    "CreateSolverByParameters",
    "ImplicitMechanicalSolver",
    "MechanicalSolver",
    "StaticMechanicalSolver",
]
