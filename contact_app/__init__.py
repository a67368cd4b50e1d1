"""contact_app: finite-element mortar contact mechanics with a Kratos-like Python API.

The compiled core (``contact_app._core``) is private; everything public is re-exported here:
the kernel classes (``Model``, ``ModelPart``, ``Node``, ...), the registry functions, and every
registered variable (``DISPLACEMENT``, ``WEIGHTED_GAP``, ...) and flag (``ACTIVE``, ``SLIP``, ...)
as a module attribute.
"""

# ruff: noqa: F401  (the core names are imported to be re-exported: ``__all__`` is made from them)

from __future__ import annotations

import importlib
import os
from typing import TYPE_CHECKING, Any

# The assembly's OpenMP threads sleep while they wait instead of spinning (docs/architecture.md,
# "Threading model"): where the cores are shared, a spinning thread holds the core its busy partner
# needs. libgomp reads the setting when _core loads it, so it is set first, never over the user's.
os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")

from . import _core  # noqa: E402
from ._core import (  # noqa: E402
    AALMAdaptPenaltyValueProcess,
    ActiveSetUtilities,
    ALMFastInit,
    ALMVariablesCalculationProcess,
    AndCriteria,
    Array1DVariable3,
    BaseMortarConvergenceCriteria,
    BoolVariable,
    BuilderAndSolver,
    CheckKrylovSettings,
    CompositeCriteria,
    ComputeDynamicFactorProcess,
    Condition,
    ConditionsArray,
    ConfigurationError,
    ConstitutiveLaw,
    ConstitutiveLawVariable,
    ContactBlockMeasure,
    ContactCriteriaTolerances,
    ContactSearchProcess,
    ContactSearchSettings,
    ContactUtilities,
    ConvergenceCriteria,
    ConvergenceError,
    CreateLinearSolver,
    DisplacementCriteria,
    DisplacementLagrangeMultiplierContactCriteria,
    Dof,
    DoubleVariable,
    Element,
    ElementsArray,
    FindNodalHProcess,
    Flags,
    Geometry,
    InputError,
    IntegerVariable,
    InterfacePreprocessCondition,
    InternalError,
    InvertedElementError,
    LinearSolver,
    LineSearchContactStrategy,
    LineSearchStrategy,
    MasterSlaveConstraint,
    MasterSlaveConstraintsArray,
    MasterSlaveProcess,
    MatrixVariable,
    MixedGenericCriteria,
    MixedULMLinearSolver,
    Model,
    ModelPart,
    ModelPartIO,
    MPCContactCriteria,
    MPCContactSearchProcess,
    MpiRankAndSize,
    Node,
    NodesArray,
    NormalCheckProcess,
    OrCriteria,
    PetscUnavailableReason,
    ProcessInfo,
    Properties,
    PropertiesArray,
    ResidualBasedBlockBuilderAndSolver,
    ResidualBasedBossakDisplacementScheme,
    ResidualBasedEliminationBuilderAndSolver,
    ResidualBasedIncrementalUpdateStaticScheme,
    ResidualBasedLinearStrategy,
    ResidualBasedNewmarkDisplacementScheme,
    ResidualBasedNewtonRaphsonContactStrategy,
    ResidualBasedNewtonRaphsonMPCContactStrategy,
    ResidualBasedNewtonRaphsonStrategy,
    ResidualCriteria,
    ResolveLinearSolverName,
    Scheme,
    SolvingStrategy,
    StaticCondensationSolver,
    StringVariable,
    Table,
    VariableData,
    VariableUtils,
    VectorVariable,
    create_constitutive_law,
    create_geometry,
    get_flag,
    get_variable,
    registered_conditions,
    registered_constitutive_laws,
    registered_constraints,
    registered_elements,
    registered_flags,
    registered_geometries,
    registered_linear_solvers,
    registered_variables,
)

__version__ = "0.1.0"


def _export_registered_names() -> list[str]:
    """Copy every registered variable and flag of the core into this module; return their names."""
    names = [*registered_variables(), *registered_flags()]
    module_globals = globals()
    for name in names:
        module_globals[name] = getattr(_core, name)
    return names


# The public names are written once, in the import list above: every module-level name bound to
# the core's object of the same name, then the registered variables and flags, then ``analysis``.
__all__ = [
    name
    for name, value in globals().items()
    if not name.startswith("_") and getattr(_core, name, None) is value
]
__all__ += _export_registered_names()
__all__ += ["analysis"]

if TYPE_CHECKING:
    from . import analysis


def __getattr__(name: str) -> Any:
    """Import ``contact_app.analysis`` on first use (it imports this package, and numpy).

    The analysis driver sits above the package: importing it eagerly here was the only upward
    import, and cost every ``import contact_app`` the driver's import time.
    """
    if name == "analysis":
        return importlib.import_module(f"{__name__}.analysis")
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted({*globals(), "analysis"})
