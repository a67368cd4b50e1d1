"""contact_app: finite-element mortar contact mechanics with a Kratos-like Python API.

The compiled core (``contact_app._core``) is private; everything public is re-exported here:
the kernel classes (``Model``, ``ModelPart``, ``Node``, ...), the registry functions, and every
registered variable (``DISPLACEMENT``, ``WEIGHTED_GAP``, ...) and flag (``ACTIVE``, ``SLIP``, ...)
as a module attribute.
"""

from __future__ import annotations

from . import _core
from ._core import (
    AndCriteria,
    Array1DVariable3,
    BoolVariable,
    BuilderAndSolver,
    CompositeCriteria,
    Condition,
    ConditionsArray,
    ConfigurationError,
    ConstitutiveLaw,
    ConstitutiveLawVariable,
    ConvergenceCriteria,
    ConvergenceError,
    CreateLinearSolver,
    DisplacementCriteria,
    Dof,
    DoubleVariable,
    Element,
    ElementsArray,
    Flags,
    Geometry,
    InputError,
    IntegerVariable,
    InternalError,
    LinearSolver,
    LineSearchStrategy,
    MasterSlaveConstraint,
    MasterSlaveConstraintsArray,
    MatrixVariable,
    MixedGenericCriteria,
    Model,
    ModelPart,
    ModelPartIO,
    Node,
    NodesArray,
    OrCriteria,
    ProcessInfo,
    Properties,
    PropertiesArray,
    ResidualBasedBlockBuilderAndSolver,
    ResidualBasedBossakDisplacementScheme,
    ResidualBasedEliminationBuilderAndSolver,
    ResidualBasedIncrementalUpdateStaticScheme,
    ResidualBasedLinearStrategy,
    ResidualBasedNewmarkDisplacementScheme,
    ResidualBasedNewtonRaphsonStrategy,
    ResidualCriteria,
    ResolveLinearSolverName,
    Scheme,
    SolvingStrategy,
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

__all__ = [
    "AndCriteria",
    "BuilderAndSolver",
    "CompositeCriteria",
    "ConvergenceCriteria",
    "CreateLinearSolver",
    "DisplacementCriteria",
    "LineSearchStrategy",
    "LinearSolver",
    "OrCriteria",
    "ResidualBasedBlockBuilderAndSolver",
    "ResidualBasedBossakDisplacementScheme",
    "ResidualBasedEliminationBuilderAndSolver",
    "ResidualBasedIncrementalUpdateStaticScheme",
    "ResidualBasedLinearStrategy",
    "ResidualBasedNewmarkDisplacementScheme",
    "ResidualBasedNewtonRaphsonStrategy",
    "ResidualCriteria",
    "ResolveLinearSolverName",
    "Scheme",
    "SolvingStrategy",
    "registered_linear_solvers",
    "Array1DVariable3",
    "BoolVariable",
    "Condition",
    "ConstitutiveLaw",
    "ConstitutiveLawVariable",
    "ConditionsArray",
    "ConfigurationError",
    "ConvergenceError",
    "Dof",
    "DoubleVariable",
    "Element",
    "ElementsArray",
    "Flags",
    "Geometry",
    "InputError",
    "IntegerVariable",
    "InternalError",
    "MasterSlaveConstraint",
    "MasterSlaveConstraintsArray",
    "MatrixVariable",
    "MixedGenericCriteria",
    "Model",
    "ModelPart",
    "ModelPartIO",
    "Node",
    "NodesArray",
    "ProcessInfo",
    "Properties",
    "PropertiesArray",
    "StringVariable",
    "Table",
    "VariableData",
    "VariableUtils",
    "VectorVariable",
    "create_constitutive_law",
    "create_geometry",
    "get_flag",
    "get_variable",
    "registered_conditions",
    "registered_constitutive_laws",
    "registered_constraints",
    "registered_elements",
    "registered_flags",
    "registered_geometries",
    "registered_variables",
]


def _export_registered_names() -> list[str]:
    """Copy every registered variable and flag of the core into this module; return their names."""
    names = [*registered_variables(), *registered_flags()]
    module_globals = globals()
    for name in names:
        module_globals[name] = getattr(_core, name)
    return names


__all__ += _export_registered_names()

from . import analysis  # noqa: E402  (needs the names above: it imports contact_app itself)

__all__ += ["analysis"]
