"""
Compiled core of contact_app (private: import contact_app instead).
"""
from __future__ import annotations
import collections.abc
from contact_app import ConfigurationError
from contact_app import ConvergenceError
from contact_app import InputError
from contact_app import InternalError
from contact_app import InvertedElementError
import numpy
import numpy.typing
import typing
from . import ActiveSetUtilities
__all__: list[str] = ['AALMAdaptPenaltyValueProcess', 'ACCELERATION', 'ACCELERATION_X', 'ACCELERATION_Y', 'ACCELERATION_Z', 'ACTIVE', 'ACTIVE_CHECK_FACTOR', 'ACTIVE_SET_COMPUTED', 'ACTIVE_SET_CONVERGED', 'ADAPT_PENALTY', 'ALMANSI_STRAIN_TENSOR', 'ALMANSI_STRAIN_VECTOR', 'ALMFastInit', 'ALMVariablesCalculationProcess', 'ANGULAR_ACCELERATION', 'ANGULAR_ACCELERATION_X', 'ANGULAR_ACCELERATION_Y', 'ANGULAR_ACCELERATION_Z', 'ANGULAR_VELOCITY', 'ANGULAR_VELOCITY_X', 'ANGULAR_VELOCITY_Y', 'ANGULAR_VELOCITY_Z', 'AREA_WEIGHTED_PAIR_GAP', 'AREA_WEIGHTED_PAIR_SLIP', 'AREA_WEIGHTED_PAIR_SLIP_X', 'AREA_WEIGHTED_PAIR_SLIP_Y', 'AREA_WEIGHTED_PAIR_SLIP_Z', 'AUGMENTED_NORMAL_CONTACT_PRESSURE', 'AUGMENTED_TANGENT_CONTACT_PRESSURE', 'AUGMENTED_TANGENT_CONTACT_PRESSURE_X', 'AUGMENTED_TANGENT_CONTACT_PRESSURE_Y', 'AUGMENTED_TANGENT_CONTACT_PRESSURE_Z', 'AUXILIAR_COORDINATES', 'AUXILIAR_COORDINATES_X', 'AUXILIAR_COORDINATES_Y', 'AUXILIAR_COORDINATES_Z', 'ActiveSetUtilities', 'AndCriteria', 'Array1DVariable3', 'BLOCKED', 'BODY_FORCE', 'BODY_FORCE_X', 'BODY_FORCE_Y', 'BODY_FORCE_Z', 'BOSSAK_ALPHA', 'BOUNDARY', 'BUILD_SCALE_FACTOR', 'BaseMortarConvergenceCriteria', 'BoolVariable', 'BuilderAndSolver', 'BulkEntities', 'BulkEntityFlags', 'BulkEntityValues', 'BulkIntegrationPointValues', 'BulkNodalCoordinates', 'BulkNodalFlags', 'BulkNodalValues', 'BulkNodeIds', 'CAUCHY_STRESS_TENSOR', 'CAUCHY_STRESS_VECTOR', 'CHECKPOINT_FORMAT_VERSION', 'COMPUTE_LUMPED_MASS_MATRIX', 'CONSIDER_NORMAL_VARIATION', 'CONSIDER_TESSELLATION', 'CONSTITUTIVE_LAW', 'CONSTITUTIVE_MATRIX', 'CONSTRAINT_POINTER', 'CONTACT', 'CONTACT_FORCE', 'CONTACT_FORCE_X', 'CONTACT_FORCE_Y', 'CONTACT_FORCE_Z', 'CONTACT_PRESSURE', 'CONVERGENCE_RATIO', 'CheckKrylovSettings', 'CompositeCriteria', 'ComputeDynamicFactorProcess', 'Condition', 'ConditionsArray', 'ConditionsArrayIterator', 'ConfigurationError', 'ConstitutiveLaw', 'ConstitutiveLawVariable', 'ContactBlockMeasure', 'ContactCriteriaTolerances', 'ContactSearchProcess', 'ContactSearchSettings', 'ContactUtilities', 'ConvergenceCriteria', 'ConvergenceError', 'CreateLinearSolver', 'DEFORMATION_GRADIENT', 'DELTA_COORDINATES', 'DELTA_COORDINATES_X', 'DELTA_COORDINATES_Y', 'DELTA_COORDINATES_Z', 'DELTA_TIME', 'DENSITY', 'DISPLACEMENT', 'DISPLACEMENT_X', 'DISPLACEMENT_Y', 'DISPLACEMENT_Z', 'DISTANCE', 'DISTANCE_THRESHOLD', 'DOMAIN_SIZE', 'DYNAMIC_FACTOR', 'DisplacementCriteria', 'DisplacementLagrangeMultiplierContactCriteria', 'Dof', 'DoubleVariable', 'ERROR_INTEGRATION_POINT', 'ERROR_RATIO', 'Element', 'ElementsArray', 'ElementsArrayIterator', 'FLUID', 'FORCE', 'FORCE_RESIDUAL', 'FORCE_RESIDUAL_X', 'FORCE_RESIDUAL_Y', 'FORCE_RESIDUAL_Z', 'FORCE_X', 'FORCE_Y', 'FORCE_Z', 'FREE_SURFACE', 'FRICTIONAL_LAW', 'FRICTION_COEFFICIENT', 'FindNodalHProcess', 'Flags', 'GREEN_LAGRANGE_STRAIN_TENSOR', 'GREEN_LAGRANGE_STRAIN_VECTOR', 'Geometry', 'IDENTIFIER', 'INDEX_MAP', 'INDEX_SET', 'INITIAL_PENALTY', 'INITIAL_STRAIN_VECTOR', 'INLET', 'INNER_LOOP_ITERATION', 'INSIDE', 'INTEGRATION_ORDER', 'INTEGRATION_ORDER_CONTACT', 'INTERACTION', 'INTERFACE', 'ISOLATED', 'IS_RESTARTED', 'InputError', 'InspectCheckpoint', 'IntegerVariable', 'InterfacePreprocessCondition', 'InternalError', 'InvertedElementError', 'LAGRANGE_MULTIPLIER_CONTACT_PRESSURE', 'LINE_LOAD', 'LINE_LOAD_X', 'LINE_LOAD_Y', 'LINE_LOAD_Z', 'LineSearchContactStrategy', 'LineSearchStrategy', 'LinearSolver', 'LoadCheckpoint', 'MARKER', 'MASS_FACTOR', 'MASTER', 'MASTER_SLAVE_CONSTRAINT', 'MAX_GAP_FACTOR', 'MAX_GAP_THRESHOLD', 'MESH_DISPLACEMENT', 'MESH_DISPLACEMENT_X', 'MESH_DISPLACEMENT_Y', 'MESH_DISPLACEMENT_Z', 'MODIFIED', 'MPCContactCriteria', 'MPCContactSearchProcess', 'MPI_BOUNDARY', 'MasterSlaveConstraint', 'MasterSlaveConstraintsArray', 'MasterSlaveConstraintsArrayIterator', 'MasterSlaveProcess', 'MatrixVariable', 'MixedGenericCriteria', 'MixedULMLinearSolver', 'Model', 'ModelPart', 'ModelPartIO', 'MortarType', 'MortarTypes', 'MpiRankAndSize', 'NEGATIVE_FACE_PRESSURE', 'NEWMARK_BETA', 'NEWMARK_GAMMA', 'NEW_ENTITY', 'NL_ITERATION_NUMBER', 'NODAL_AREA', 'NODAL_H', 'NODAL_MASS', 'NODAL_MAUX', 'NODAL_PAUX', 'NODAL_VAUX', 'NODAL_VAUX_X', 'NODAL_VAUX_Y', 'NODAL_VAUX_Z', 'NORMAL', 'NORMAL_CONTACT_STRESS', 'NORMAL_GAP', 'NORMAL_X', 'NORMAL_Y', 'NORMAL_Z', 'Node', 'NodesArray', 'NodesArrayIterator', 'NormalCheckProcess', 'OLD_ENTITY', 'OPERATOR_THRESHOLD', 'OUTLET', 'OrCriteria', 'PAIRED_NORMAL', 'PAIRED_NORMAL_X', 'PAIRED_NORMAL_Y', 'PAIRED_NORMAL_Z', 'PERIODIC', 'PK2_STRESS_TENSOR', 'PK2_STRESS_VECTOR', 'POINT_LOAD', 'POINT_LOAD_X', 'POINT_LOAD_Y', 'POINT_LOAD_Z', 'POINT_MOMENT', 'POINT_MOMENT_X', 'POINT_MOMENT_Y', 'POINT_MOMENT_Z', 'POISSON_RATIO', 'POSITIVE_FACE_PRESSURE', 'PRESSURE', 'PetscUnavailableReason', 'ProcessInfo', 'Properties', 'PropertiesArray', 'PropertiesArrayIterator', 'RAYLEIGH_ALPHA', 'RAYLEIGH_BETA', 'REACTION', 'REACTION_CHECK_STIFFNESS_FACTOR', 'REACTION_MOMENT', 'REACTION_MOMENT_X', 'REACTION_MOMENT_Y', 'REACTION_MOMENT_Z', 'REACTION_X', 'REACTION_Y', 'REACTION_Z', 'RESET_EQUATION_IDS', 'RESIDUAL_NORM', 'RESTART_PROCESS_STATES', 'RIGID', 'ROTATION', 'ROTATION_X', 'ROTATION_Y', 'ROTATION_Z', 'ResidualBasedBlockBuilderAndSolver', 'ResidualBasedBossakDisplacementScheme', 'ResidualBasedEliminationBuilderAndSolver', 'ResidualBasedIncrementalUpdateStaticScheme', 'ResidualBasedLinearStrategy', 'ResidualBasedNewmarkDisplacementScheme', 'ResidualBasedNewtonRaphsonContactStrategy', 'ResidualBasedNewtonRaphsonMPCContactStrategy', 'ResidualBasedNewtonRaphsonStrategy', 'ResidualCriteria', 'ResolveLinearSolverName', 'SCALAR_LAGRANGE_MULTIPLIER', 'SCALE_FACTOR', 'SELECTED', 'SLAVE', 'SLIP', 'SLIP_AUGMENTATION_COEFFICIENT', 'SLIP_SET_CONVERGED', 'SLIP_THRESHOLD', 'SLIP_TRIAL_FACTOR', 'SOLID', 'SQUARED_PAIR_AREA', 'STEP', 'STRAIN_ENERGY', 'STRUCTURE', 'SURFACE_LOAD', 'SURFACE_LOAD_X', 'SURFACE_LOAD_Y', 'SURFACE_LOAD_Z', 'SaveCheckpoint', 'Scheme', 'SolvingStrategy', 'StaticCondensationSolver', 'StringVariable', 'TABLE_UTILITY', 'TANGENTIAL_CONTACT_STRESS', 'TANGENT_ETA', 'TANGENT_ETA_X', 'TANGENT_ETA_Y', 'TANGENT_ETA_Z', 'TANGENT_FACTOR', 'TANGENT_SLIP', 'TANGENT_SLIP_X', 'TANGENT_SLIP_Y', 'TANGENT_SLIP_Z', 'TANGENT_XI', 'TANGENT_XI_X', 'TANGENT_XI_Y', 'TANGENT_XI_Z', 'TEMPERATURE', 'THERMAL', 'THICKNESS', 'TIME', 'TO_ERASE', 'TO_REFINE', 'TO_SPLIT', 'TRESCA_FRICTION_THRESHOLD', 'TYING_VARIABLE', 'Table', 'VECTOR_LAGRANGE_MULTIPLIER', 'VECTOR_LAGRANGE_MULTIPLIER_X', 'VECTOR_LAGRANGE_MULTIPLIER_Y', 'VECTOR_LAGRANGE_MULTIPLIER_Z', 'VELOCITY', 'VELOCITY_X', 'VELOCITY_Y', 'VELOCITY_Z', 'VISITED', 'VOLUME_ACCELERATION', 'VOLUME_ACCELERATION_X', 'VOLUME_ACCELERATION_Y', 'VOLUME_ACCELERATION_Z', 'VON_MISES_STRESS', 'VariableData', 'VariableUtils', 'VectorVariable', 'WEIGHTED_GAP', 'WEIGHTED_SCALAR_RESIDUAL', 'WEIGHTED_SLIP', 'WEIGHTED_SLIP_X', 'WEIGHTED_SLIP_Y', 'WEIGHTED_SLIP_Z', 'WEIGHTED_VECTOR_RESIDUAL', 'WEIGHTED_VECTOR_RESIDUAL_X', 'WEIGHTED_VECTOR_RESIDUAL_Y', 'WEIGHTED_VECTOR_RESIDUAL_Z', 'YOUNG_MODULUS', 'ZERO_TOLERANCE_FACTOR', 'create_constitutive_law', 'create_geometry', 'get_flag', 'get_variable', 'registered_conditions', 'registered_constitutive_laws', 'registered_constraints', 'registered_elements', 'registered_flags', 'registered_geometries', 'registered_linear_solvers', 'registered_variables']
class VariableData:
    """
    Type-erased part of a variable.
    """
    def GetComponentIndex(self) -> int:
        """
        Component index 0..2 (0 if not a component).
        """
    def GetSourceVariable(self) -> typing.Any:
        """
        The 3-vector variable of a component (None otherwise).
        """
    def IsComponent(self) -> bool:
        """
        True for DISPLACEMENT_X-like component variables.
        """
    def Key(self) -> int:
        """
        Dense registry key (0, 1, 2, ...).
        """
    def Name(self) -> str:
        """
        The Kratos name, e.g. "DISPLACEMENT_X".
        """
    def Type(self) -> str:
        """
        Kratos type string: Bool, Integer, Double, Component, Array, Vector, Matrix, String, Pointer.
        """
    def __eq__(self, arg0: VariableData) -> bool:
        """
        Variables compare by key.
        """
    def __hash__(self) -> int:
        """
        Hash of the key.
        """
    def __repr__(self) -> str:
        """
        <DoubleVariable YOUNG_MODULUS>.
        """
    def __str__(self) -> str:
        """
        The name.
        """
class BoolVariable(VariableData):
    """
    A bool variable (Kratos Variable<bool>).
    """
    def Zero(self) -> bool:
        """
        The value an unset entry reads as.
        """
class IntegerVariable(VariableData):
    """
    An int variable (Kratos Variable<int>).
    """
    def Zero(self) -> int:
        """
        The value an unset entry reads as.
        """
class DoubleVariable(VariableData):
    """
    A double variable or a component (DISPLACEMENT_X).
    """
    def Zero(self) -> float:
        """
        The value an unset entry reads as.
        """
class Array1DVariable3(VariableData):
    """
    A 3-vector variable (Kratos Variable<array_1d<double,3>>).
    """
    def Zero(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        The value an unset entry reads as.
        """
class VectorVariable(VariableData):
    """
    A vector variable (Kratos Variable<Vector>).
    """
    def Zero(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        The value an unset entry reads as.
        """
class MatrixVariable(VariableData):
    """
    A matrix variable (Kratos Variable<Matrix>).
    """
    def Zero(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        The value an unset entry reads as.
        """
class StringVariable(VariableData):
    """
    A string variable (Kratos Variable<std::string>).
    """
    def Zero(self) -> str:
        """
        The value an unset entry reads as.
        """
class ConstitutiveLawVariable(VariableData):
    """
    The CONSTITUTIVE_LAW variable (holds a law object in Properties).
    """
class Flags:
    """
    Up to 64 tri-state flags (Kratos Flags).
    """
    def AsFalse(self) -> Flags:
        """
        The same bits, defined and reset.
        """
    def Clear(self) -> None:
        """
        Makes every flag undefined.
        """
    def Flip(self, flag: Flags) -> None:
        """
        Negates (and defines) the bits of flag.
        """
    def Is(self, flag: Flags) -> bool:
        """
        True if every bit defined in flag has the value flag gives it.
        """
    def IsDefined(self, flag: Flags) -> bool:
        """
        True if every bit of flag is defined here.
        """
    def IsNot(self, flag: Flags) -> bool:
        """
        not Is(flag).
        """
    def IsNotDefined(self, flag: Flags) -> bool:
        """
        not IsDefined(flag).
        """
    def Reset(self, flag: Flags) -> None:
        """
        Makes the bits of flag undefined again.
        """
    def Set(self, flag: Flags, value: bool = True) -> None:
        """
        Defines the bits of flag with value.
        """
    def __eq__(self, arg0: Flags) -> bool:
        """
        Same defined bits with the same values.
        """
    def __hash__(self) -> int:
        """
        Hash of the bits.
        """
    def __init__(self) -> None:
        """
        All flags undefined.
        """
    def __or__(self, arg0: Flags) -> Flags:
        """
        Union of the defined bits.
        """
    def __repr__(self) -> str:
        """
        Flags(ACTIVE, SLIP=False).
        """
class Table:
    """
    Piecewise-linear table y(x) (Kratos Table).
    """
    def AddRow(self, x: typing.SupportsFloat | typing.SupportsIndex, y: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        Inserts a row (kept sorted by x).
        """
    def Data(self) -> list[tuple[float, float]]:
        """
        The rows as (x, y) tuples.
        """
    def GetDerivative(self, x: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        dy/dx of the segment containing x.
        """
    def GetValue(self, x: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        y(x), linearly interpolated or extrapolated.
        """
    def PushBack(self, x: typing.SupportsFloat | typing.SupportsIndex, y: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        Same as AddRow.
        """
    def Size(self) -> int:
        """
        Number of rows.
        """
    def __init__(self) -> None:
        """
        An empty table.
        """
    def __len__(self) -> int:
        """
        Number of rows.
        """
    def __repr__(self) -> str:
        """
        <Table with n rows>.
        """
class ConstitutiveLaw:
    """
    A material law (Kratos ConstitutiveLaw).
    """
    def Clone(self) -> ConstitutiveLaw:
        """
        An independent copy.
        """
    def GetStrainSize(self) -> int:
        """
        Number of Voigt strain components.
        """
    def Info(self) -> str:
        """
        The law's name.
        """
    def WorkingSpaceDimension(self) -> int:
        """
        2 or 3.
        """
    def __repr__(self) -> str:
        ...
class Properties:
    """
    Material and condition parameters shared by entities (Kratos Properties).
    """
    def CopyValuesFrom(self, other: Properties) -> None:
        """
        Replaces the stored values (not the tables) by those of other; the contact processes give each pair property the material values of its body this way.
        """
    def GetTable(self, input_variable: VariableData, output_variable: VariableData) -> Table:
        """
        The table; InputError if there is none.
        """
    @typing.overload
    def GetValue(self, variable: ConstitutiveLawVariable) -> ConstitutiveLaw:
        """
        The constitutive law (None if unset).
        """
    @typing.overload
    def GetValue(self, variable: BoolVariable) -> bool:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: IntegerVariable) -> int:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: DoubleVariable) -> float:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: Array1DVariable3) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: VectorVariable) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: MatrixVariable) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: StringVariable) -> str:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: VariableData) -> None:
        """
        Pointer variables cannot be read from Python.
        """
    def Has(self, variable: VariableData) -> bool:
        """
        True if a value is stored for the variable.
        """
    def HasTable(self, input_variable: VariableData, output_variable: VariableData) -> bool:
        """
        True if a table maps input_variable to output_variable.
        """
    def NumberOfTables(self) -> int:
        """
        Number of tables.
        """
    def SetTable(self, input_variable: VariableData, output_variable: VariableData, table: Table) -> None:
        """
        Stores a copy of table for (input_variable, output_variable).
        """
    @typing.overload
    def SetValue(self, variable: ConstitutiveLawVariable, value: ConstitutiveLaw) -> None:
        """
        Stores the constitutive law.
        """
    @typing.overload
    def SetValue(self, variable: BoolVariable, value: bool) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: IntegerVariable, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: DoubleVariable, value: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: Array1DVariable3, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: VectorVariable, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: MatrixVariable, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: StringVariable, value: str) -> None:
        """
        Stores a value for the variable.
        """
    def __contains__(self, variable: VariableData) -> bool:
        """
        Same as Has(variable).
        """
    def __eq__(self, arg0: Properties) -> bool:
        """
        Same C++ object.
        """
    @typing.overload
    def __getitem__(self, variable: ConstitutiveLawVariable) -> ConstitutiveLaw:
        """
        The constitutive law (None if unset).
        """
    @typing.overload
    def __getitem__(self, variable: BoolVariable) -> bool:
        """
        Same as GetValue(variable).
        """
    @typing.overload
    def __getitem__(self, variable: IntegerVariable) -> int:
        """
        Same as GetValue(variable).
        """
    @typing.overload
    def __getitem__(self, variable: DoubleVariable) -> float:
        """
        Same as GetValue(variable).
        """
    @typing.overload
    def __getitem__(self, variable: Array1DVariable3) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        Same as GetValue(variable).
        """
    @typing.overload
    def __getitem__(self, variable: VectorVariable) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        Same as GetValue(variable).
        """
    @typing.overload
    def __getitem__(self, variable: MatrixVariable) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Same as GetValue(variable).
        """
    @typing.overload
    def __getitem__(self, variable: StringVariable) -> str:
        """
        Same as GetValue(variable).
        """
    @typing.overload
    def __getitem__(self, variable: VariableData) -> None:
        """
        Pointer variables cannot be read from Python.
        """
    def __hash__(self) -> int:
        """
        Hash of the address.
        """
    def __init__(self, id: typing.SupportsInt | typing.SupportsIndex) -> None:
        """
        Stand-alone properties (use ModelPart.CreateNewProperties).
        """
    def __repr__(self) -> str:
        """
        <Properties id: stored variables>.
        """
    @typing.overload
    def __setitem__(self, variable: ConstitutiveLawVariable, value: ConstitutiveLaw) -> None:
        """
        Stores the constitutive law.
        """
    @typing.overload
    def __setitem__(self, variable: BoolVariable, value: bool) -> None:
        """
        Same as SetValue(variable, value).
        """
    @typing.overload
    def __setitem__(self, variable: IntegerVariable, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        """
        Same as SetValue(variable, value).
        """
    @typing.overload
    def __setitem__(self, variable: DoubleVariable, value: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        Same as SetValue(variable, value).
        """
    @typing.overload
    def __setitem__(self, variable: Array1DVariable3, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"]) -> None:
        """
        Same as SetValue(variable, value).
        """
    @typing.overload
    def __setitem__(self, variable: VectorVariable, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> None:
        """
        Same as SetValue(variable, value).
        """
    @typing.overload
    def __setitem__(self, variable: MatrixVariable, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        """
        Same as SetValue(variable, value).
        """
    @typing.overload
    def __setitem__(self, variable: StringVariable, value: str) -> None:
        """
        Same as SetValue(variable, value).
        """
    @property
    def Id(self) -> int:
        """
        Properties id.
        """
class ProcessInfo(Flags):
    """
    Global values of an analysis (Kratos ProcessInfo): TIME, DELTA_TIME, STEP, switches.
    """
    @typing.overload
    def GetValue(self, variable: BoolVariable) -> bool:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: IntegerVariable) -> int:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: DoubleVariable) -> float:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: Array1DVariable3) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: VectorVariable) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: MatrixVariable) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: StringVariable) -> str:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: VariableData) -> None:
        """
        Pointer variables cannot be read from Python.
        """
    def Has(self, variable: VariableData) -> bool:
        """
        True if a value is stored for the variable.
        """
    @typing.overload
    def SetValue(self, variable: BoolVariable, value: bool) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: IntegerVariable, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: DoubleVariable, value: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: Array1DVariable3, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: VectorVariable, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: MatrixVariable, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: StringVariable, value: str) -> None:
        """
        Stores a value for the variable.
        """
    def __contains__(self, variable: VariableData) -> bool:
        """
        Same as Has(variable).
        """
    def __eq__(self, arg0: ProcessInfo) -> bool:
        """
        Same C++ object.
        """
    @typing.overload
    def __getitem__(self, variable: BoolVariable) -> bool:
        """
        Same as GetValue(variable).
        """
    @typing.overload
    def __getitem__(self, variable: IntegerVariable) -> int:
        """
        Same as GetValue(variable).
        """
    @typing.overload
    def __getitem__(self, variable: DoubleVariable) -> float:
        """
        Same as GetValue(variable).
        """
    @typing.overload
    def __getitem__(self, variable: Array1DVariable3) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        Same as GetValue(variable).
        """
    @typing.overload
    def __getitem__(self, variable: VectorVariable) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        Same as GetValue(variable).
        """
    @typing.overload
    def __getitem__(self, variable: MatrixVariable) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Same as GetValue(variable).
        """
    @typing.overload
    def __getitem__(self, variable: StringVariable) -> str:
        """
        Same as GetValue(variable).
        """
    @typing.overload
    def __getitem__(self, variable: VariableData) -> None:
        """
        Pointer variables cannot be read from Python.
        """
    def __hash__(self) -> int:
        """
        Hash of the address.
        """
    def __init__(self) -> None:
        """
        An empty ProcessInfo.
        """
    def __repr__(self) -> str:
        """
        <ProcessInfo: stored variables>.
        """
    @typing.overload
    def __setitem__(self, variable: BoolVariable, value: bool) -> None:
        """
        Same as SetValue(variable, value).
        """
    @typing.overload
    def __setitem__(self, variable: IntegerVariable, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        """
        Same as SetValue(variable, value).
        """
    @typing.overload
    def __setitem__(self, variable: DoubleVariable, value: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        Same as SetValue(variable, value).
        """
    @typing.overload
    def __setitem__(self, variable: Array1DVariable3, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"]) -> None:
        """
        Same as SetValue(variable, value).
        """
    @typing.overload
    def __setitem__(self, variable: VectorVariable, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> None:
        """
        Same as SetValue(variable, value).
        """
    @typing.overload
    def __setitem__(self, variable: MatrixVariable, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        """
        Same as SetValue(variable, value).
        """
    @typing.overload
    def __setitem__(self, variable: StringVariable, value: str) -> None:
        """
        Same as SetValue(variable, value).
        """
class Dof:
    """
    A degree of freedom of a node (owned by it).
    """
    def Fix(self) -> None:
        """
        Fixes the DoF.
        """
    def Free(self) -> None:
        """
        Frees the DoF.
        """
    def GetReaction(self) -> DoubleVariable:
        """
        The reaction variable (REACTION_X).
        """
    def GetSolutionStepReactionValue(self, step: typing.SupportsInt | typing.SupportsIndex = 0) -> float:
        """
        Value of the reaction at buffer step.
        """
    def GetSolutionStepValue(self, step: typing.SupportsInt | typing.SupportsIndex = 0) -> float:
        """
        Value of the unknown at buffer step.
        """
    def GetVariable(self) -> DoubleVariable:
        """
        The unknown (DISPLACEMENT_X).
        """
    def HasReaction(self) -> bool:
        """
        True if a reaction variable is set.
        """
    def Id(self) -> int:
        """
        Id of the owning node.
        """
    def IsFixed(self) -> bool:
        """
        True if fixed.
        """
    def IsFree(self) -> bool:
        """
        True if free.
        """
    def __repr__(self) -> str:
        """
        <Dof DISPLACEMENT_X of node 3 (fixed)>.
        """
    @property
    def EquationId(self) -> int:
        """
        Row of the DoF in the global system.
        """
    @EquationId.setter
    def EquationId(self, arg1: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
class Node(Flags):
    """
    A mesh node (Kratos Node): coordinates, flags, historical and non-historical data, DoFs.
    """
    @typing.overload
    def AddDof(self, variable: DoubleVariable, reaction: DoubleVariable) -> Dof:
        """
        Adds (or returns) the DoF of variable with its reaction variable.
        """
    @typing.overload
    def AddDof(self, variable: DoubleVariable) -> Dof:
        """
        Adds (or returns) the DoF of variable.
        """
    def CloneSolutionStep(self) -> None:
        """
        Shifts the buffer: step 0 is copied into a new step 0.
        """
    def Coordinates(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        Copy of the current coordinates.
        """
    def Fix(self, variable: DoubleVariable) -> None:
        """
        Fixes the DoF of variable (adding it if needed).
        """
    def Free(self, variable: VariableData) -> None:
        """
        Frees the DoF of variable; InputError if there is none.
        """
    def GetBufferSize(self) -> int:
        """
        Number of buffer steps.
        """
    def GetDof(self, variable: VariableData) -> Dof:
        """
        The DoF of variable; InputError if there is none.
        """
    def GetDofs(self) -> list:
        """
        Every DoF of the node, in insertion order.
        """
    @typing.overload
    def GetSolutionStepValue(self, variable: DoubleVariable, step: typing.SupportsInt | typing.SupportsIndex = 0) -> float:
        """
        Historical value at buffer step (0: current step).
        """
    @typing.overload
    def GetSolutionStepValue(self, variable: Array1DVariable3, step: typing.SupportsInt | typing.SupportsIndex = 0) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        Historical value at buffer step (0: current step).
        """
    @typing.overload
    def GetSolutionStepValue(self, variable: VariableData, step: typing.SupportsInt | typing.SupportsIndex = 0) -> None:
        """
        Other variable kinds are not historical.
        """
    @typing.overload
    def GetValue(self, variable: BoolVariable) -> bool:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: IntegerVariable) -> int:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: DoubleVariable) -> float:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: Array1DVariable3) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: VectorVariable) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: MatrixVariable) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: StringVariable) -> str:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: VariableData) -> None:
        """
        Pointer variables cannot be read from Python.
        """
    def Has(self, variable: VariableData) -> bool:
        """
        True if a value is stored for the variable.
        """
    def HasDofFor(self, variable: VariableData) -> bool:
        """
        True if the node has a DoF for variable.
        """
    def InitialCoordinates(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        Copy of the initial coordinates.
        """
    def IsFixed(self, variable: VariableData) -> bool:
        """
        True if the DoF of variable exists and is fixed.
        """
    def SetCoordinates(self, coordinates: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"]) -> None:
        """
        Sets the current coordinates.
        """
    def SetInitialCoordinates(self, coordinates: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"]) -> None:
        """
        Sets the initial coordinates.
        """
    @typing.overload
    def SetSolutionStepValue(self, variable: DoubleVariable, step: typing.SupportsInt | typing.SupportsIndex, value: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        Sets the historical value at buffer step.
        """
    @typing.overload
    def SetSolutionStepValue(self, variable: DoubleVariable, value: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        Sets the historical value of the current step.
        """
    @typing.overload
    def SetSolutionStepValue(self, variable: Array1DVariable3, step: typing.SupportsInt | typing.SupportsIndex, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"]) -> None:
        """
        Sets the historical value at buffer step.
        """
    @typing.overload
    def SetSolutionStepValue(self, variable: Array1DVariable3, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"]) -> None:
        """
        Sets the historical value of the current step.
        """
    @typing.overload
    def SetSolutionStepValue(self, variable: VariableData, step: typing.SupportsInt | typing.SupportsIndex, value: typing.Any) -> None:
        """
        Sets the historical value at buffer step, converting the value.
        """
    @typing.overload
    def SetSolutionStepValue(self, variable: VariableData, value: typing.Any) -> None:
        """
        Sets the historical value of the current step, converting the value.
        """
    @typing.overload
    def SetValue(self, variable: BoolVariable, value: bool) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: IntegerVariable, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: DoubleVariable, value: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: Array1DVariable3, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: VectorVariable, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: MatrixVariable, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: StringVariable, value: str) -> None:
        """
        Stores a value for the variable.
        """
    def SolutionStepsDataHas(self, variable: VariableData) -> bool:
        """
        True if the variable is a historical variable of the node.
        """
    def __eq__(self, arg0: Node) -> bool:
        """
        Same C++ object.
        """
    def __hash__(self) -> int:
        """
        Hash of the address.
        """
    def __init__(self, id: typing.SupportsInt | typing.SupportsIndex, x: typing.SupportsFloat | typing.SupportsIndex, y: typing.SupportsFloat | typing.SupportsIndex, z: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        A free node without historical data (use ModelPart.CreateNewNode for a mesh node).
        """
    def __repr__(self) -> str:
        """
        <Node 3 at (x, y, z)>.
        """
    @property
    def Id(self) -> int:
        """
        Node id.
        """
    @property
    def X(self) -> float:
        """
        Current x.
        """
    @X.setter
    def X(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def X0(self) -> float:
        """
        Initial x.
        """
    @X0.setter
    def X0(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def Y(self) -> float:
        """
        Current y.
        """
    @Y.setter
    def Y(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def Y0(self) -> float:
        """
        Initial y.
        """
    @Y0.setter
    def Y0(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def Z(self) -> float:
        """
        Current z.
        """
    @Z.setter
    def Z(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def Z0(self) -> float:
        """
        Initial z.
        """
    @Z0.setter
    def Z0(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class Geometry:
    """
    A finite-element geometry: nodes and shape functions.
    """
    class Configuration:
        """
        Which node coordinates a mapping uses.
        
        Members:
        
          Current
        
          Initial
        """
        Current: typing.ClassVar[Geometry.Configuration]
        Initial: typing.ClassVar[Geometry.Configuration]
        __members__: typing.ClassVar[dict[str, Geometry.Configuration]]
        @typing.overload
        def __eq__(self, other: Geometry.Configuration) -> bool:
            ...
        @typing.overload
        def __eq__(self, other: typing.Any) -> bool:
            ...
        def __getstate__(self) -> int:
            ...
        def __hash__(self) -> int:
            ...
        def __index__(self) -> int:
            ...
        def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
            ...
        def __int__(self) -> int:
            ...
        @typing.overload
        def __ne__(self, other: Geometry.Configuration) -> bool:
            ...
        @typing.overload
        def __ne__(self, other: typing.Any) -> bool:
            ...
        def __repr__(self) -> str:
            ...
        def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
            ...
        def __str__(self) -> str:
            ...
        @property
        def name(self) -> str:
            ...
        @property
        def value(self) -> int:
            ...
    def Area(self) -> float:
        """
        Area of a surface.
        """
    def Center(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        Average of the current node coordinates.
        """
    def DefaultIntegrationOrder(self) -> int:
        """
        Kratos default integration order.
        """
    def DeterminantOfJacobian(self, local: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], configuration: Geometry.Configuration = ...) -> float:
        """
        det J (signed for square J; |J| or |J0 x J1| otherwise).
        """
    def DomainSize(self) -> float:
        """
        Length, area or volume by local dimension.
        """
    def FacesNumber(self) -> int:
        """
        Number of boundary entities.
        """
    def GetGeometryPart(self, index: typing.SupportsInt | typing.SupportsIndex) -> Geometry:
        """
        Part index (0 slave, 1 master).
        """
    def GlobalCoordinates(self, local: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], configuration: Geometry.Configuration = ...) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        x(local) = sum_k N_k(local) x_k.
        """
    def IntegrationPoints(self, order: typing.SupportsInt | typing.SupportsIndex | None = None) -> list:
        """
        Gauss points as (local, weight) tuples (default order if None).
        """
    def InverseOfJacobian(self, local: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], configuration: Geometry.Configuration = ...) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Inverse of a square Jacobian.
        """
    def IsInside(self, global_coordinates: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], tolerance: typing.SupportsFloat | typing.SupportsIndex = 1e-09) -> tuple[bool, typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]]:
        """
        (inside, local coordinates) of a global point.
        """
    def Jacobian(self, local: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], configuration: Geometry.Configuration = ...) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        J (working dimension x local dimension) at local coordinates.
        """
    def Length(self) -> float:
        """
        Length of a line.
        """
    def LocalFacesConnectivity(self) -> list[list[int]]:
        """
        Local node indices of each boundary entity.
        """
    def LocalSpaceDimension(self) -> int:
        """
        Dimension of the reference element (0..3).
        """
    def Name(self) -> str:
        """
        Kratos name of the geometry type ("Quadrilateral2D4").
        """
    def Normal(self, local: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        Normal at local coordinates (magnitude det J).
        """
    def NumberOfGeometryParts(self) -> int:
        """
        Parts of a coupling geometry (0 otherwise).
        """
    def PointLocalCoordinates(self, global_coordinates: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        Local coordinates of a global point (current configuration).
        """
    def PointsLocalCoordinates(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Local coordinates of the nodes (nodes x local dimension).
        """
    def PointsNumber(self) -> int:
        """
        Number of nodes.
        """
    def ShapeFunctionValue(self, index: typing.SupportsInt | typing.SupportsIndex, local: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> float:
        """
        N_index(local).
        """
    def ShapeFunctionsLocalGradients(self, local: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        dN_k/dxi_j (nodes x local dimension).
        """
    def ShapeFunctionsValues(self, local: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        N_k(local) for every node.
        """
    def UnitNormal(self, local: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        Unit normal at local coordinates.
        """
    def Volume(self) -> float:
        """
        Volume of a solid.
        """
    def WorkingSpaceDimension(self) -> int:
        """
        Dimension of the space of the nodes (2 or 3).
        """
    def __getitem__(self, index: typing.SupportsInt | typing.SupportsIndex) -> Node:
        """
        Node index (negative counts from the end).
        """
    def __iter__(self) -> collections.abc.Iterator:
        """
        Iterates over the nodes.
        """
    def __len__(self) -> int:
        """
        Number of nodes.
        """
    def __repr__(self) -> str:
        """
        <Quadrilateral2D4 [1, 2, 3, 4]>.
        """
class Element(Flags):
    """
    A domain element (Kratos Element); the base class is a geometry-only mesh element.
    """
    def AddExplicitContribution(self, process_info: ProcessInfo) -> None:
        """
        Explicit nodal contributions (weighted gap, slip, nodal area).
        """
    def CalculateDampingMatrix(self, process_info: ProcessInfo) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Damping matrix.
        """
    def CalculateLeftHandSide(self, process_info: ProcessInfo) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        LHS of the local system.
        """
    def CalculateLocalSystem(self, process_info: ProcessInfo) -> tuple[typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"], typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]]:
        """
        (LHS, RHS) of the local system.
        """
    def CalculateMassMatrix(self, process_info: ProcessInfo) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Mass matrix.
        """
    @typing.overload
    def CalculateOnIntegrationPoints(self, variable: DoubleVariable, process_info: ProcessInfo) -> list[float]:
        """
        One value per integration point.
        """
    @typing.overload
    def CalculateOnIntegrationPoints(self, variable: Array1DVariable3, process_info: ProcessInfo) -> list[typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]]:
        """
        One value per integration point.
        """
    @typing.overload
    def CalculateOnIntegrationPoints(self, variable: VectorVariable, process_info: ProcessInfo) -> list[typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]]:
        """
        One value per integration point.
        """
    @typing.overload
    def CalculateOnIntegrationPoints(self, variable: MatrixVariable, process_info: ProcessInfo) -> list[typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]]:
        """
        One value per integration point.
        """
    def CalculateRightHandSide(self, process_info: ProcessInfo) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        RHS of the local system.
        """
    def Check(self, process_info: ProcessInfo) -> int:
        """
        0, or InputError naming what is missing.
        """
    def EquationIdVector(self, process_info: ProcessInfo) -> list[int]:
        """
        Equation ids in local-system order.
        """
    def FinalizeNonLinearIteration(self, process_info: ProcessInfo) -> None:
        """
        Called after each non-linear iteration.
        """
    def FinalizeSolutionStep(self, process_info: ProcessInfo) -> None:
        """
        Called at the end of each step.
        """
    def GetDofList(self, process_info: ProcessInfo) -> list:
        """
        DoFs in local-system order.
        """
    def GetGeometry(self) -> Geometry:
        """
        The geometry (for paired conditions: the slave one).
        """
    def GetNodes(self) -> list[Node]:
        """
        The nodes of the geometry.
        """
    def GetProperties(self) -> Properties:
        """
        The properties; InputError if none were assigned.
        """
    @typing.overload
    def GetValue(self, variable: BoolVariable) -> bool:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: IntegerVariable) -> int:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: DoubleVariable) -> float:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: Array1DVariable3) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: VectorVariable) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: MatrixVariable) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: StringVariable) -> str:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: VariableData) -> None:
        """
        Pointer variables cannot be read from Python.
        """
    def GetValuesVector(self, step: typing.SupportsInt | typing.SupportsIndex = 0) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        DoF values at buffer step, in local-system order.
        """
    def Has(self, variable: VariableData) -> bool:
        """
        True if a value is stored for the variable.
        """
    def Info(self) -> str:
        """
        Short description.
        """
    def Initialize(self, process_info: ProcessInfo) -> None:
        """
        Called once before the analysis.
        """
    def InitializeNonLinearIteration(self, process_info: ProcessInfo) -> None:
        """
        Called before each non-linear iteration.
        """
    def InitializeSolutionStep(self, process_info: ProcessInfo) -> None:
        """
        Called at the start of each step.
        """
    @typing.overload
    def SetValue(self, variable: BoolVariable, value: bool) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: IntegerVariable, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: DoubleVariable, value: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: Array1DVariable3, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: VectorVariable, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: MatrixVariable, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: StringVariable, value: str) -> None:
        """
        Stores a value for the variable.
        """
    def WhyStiffnessVaries(self) -> str:
        """
        Why the tangent stiffness may change with the displacement, "" if it cannot while the properties stay; completes "element <id> ...".
        """
    def __eq__(self, arg0: Element) -> bool:
        """
        Same C++ object.
        """
    def __hash__(self) -> int:
        """
        Hash of the address.
        """
    def __repr__(self) -> str:
        """
        <Info()>.
        """
    @property
    def Id(self) -> int:
        """
        Id.
        """
    @property
    def Properties(self) -> Properties:
        """
        The properties (None if unset).
        """
    @Properties.setter
    def Properties(self, arg1: Properties) -> None:
        ...
class Condition(Flags):
    """
    A boundary or interface condition (Kratos Condition).
    """
    def AddExplicitContribution(self, process_info: ProcessInfo) -> None:
        """
        Explicit nodal contributions (weighted gap, slip, nodal area).
        """
    def CalculateDampingMatrix(self, process_info: ProcessInfo) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Damping matrix.
        """
    def CalculateLeftHandSide(self, process_info: ProcessInfo) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        LHS of the local system.
        """
    def CalculateLocalSystem(self, process_info: ProcessInfo) -> tuple[typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"], typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]]:
        """
        (LHS, RHS) of the local system.
        """
    def CalculateMassMatrix(self, process_info: ProcessInfo) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Mass matrix.
        """
    @typing.overload
    def CalculateOnIntegrationPoints(self, variable: DoubleVariable, process_info: ProcessInfo) -> list[float]:
        """
        One value per integration point.
        """
    @typing.overload
    def CalculateOnIntegrationPoints(self, variable: Array1DVariable3, process_info: ProcessInfo) -> list[typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]]:
        """
        One value per integration point.
        """
    @typing.overload
    def CalculateOnIntegrationPoints(self, variable: VectorVariable, process_info: ProcessInfo) -> list[typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]]:
        """
        One value per integration point.
        """
    @typing.overload
    def CalculateOnIntegrationPoints(self, variable: MatrixVariable, process_info: ProcessInfo) -> list[typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]]:
        """
        One value per integration point.
        """
    def CalculateRightHandSide(self, process_info: ProcessInfo) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        RHS of the local system.
        """
    def Check(self, process_info: ProcessInfo) -> int:
        """
        0, or InputError naming what is missing.
        """
    def EquationIdVector(self, process_info: ProcessInfo) -> list[int]:
        """
        Equation ids in local-system order.
        """
    def FinalizeNonLinearIteration(self, process_info: ProcessInfo) -> None:
        """
        Called after each non-linear iteration.
        """
    def FinalizeSolutionStep(self, process_info: ProcessInfo) -> None:
        """
        Called at the end of each step.
        """
    def GetDofList(self, process_info: ProcessInfo) -> list:
        """
        DoFs in local-system order.
        """
    def GetGeometry(self) -> Geometry:
        """
        The geometry (for paired conditions: the slave one).
        """
    def GetNodes(self) -> list[Node]:
        """
        The nodes of the geometry.
        """
    def GetPairedGeometry(self) -> Geometry:
        """
        The master face of a paired condition; InputError for other conditions or unpaired ones.
        """
    def GetParentGeometry(self) -> Geometry:
        """
        The slave face of a paired condition.
        """
    def GetProperties(self) -> Properties:
        """
        The properties; InputError if none were assigned.
        """
    @typing.overload
    def GetValue(self, variable: BoolVariable) -> bool:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: IntegerVariable) -> int:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: DoubleVariable) -> float:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: Array1DVariable3) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: VectorVariable) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: MatrixVariable) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: StringVariable) -> str:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: VariableData) -> None:
        """
        Pointer variables cannot be read from Python.
        """
    def GetValuesVector(self, step: typing.SupportsInt | typing.SupportsIndex = 0) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        DoF values at buffer step, in local-system order.
        """
    def Has(self, variable: VariableData) -> bool:
        """
        True if a value is stored for the variable.
        """
    def Info(self) -> str:
        """
        Short description.
        """
    def Initialize(self, process_info: ProcessInfo) -> None:
        """
        Called once before the analysis.
        """
    def InitializeNonLinearIteration(self, process_info: ProcessInfo) -> None:
        """
        Called before each non-linear iteration.
        """
    def InitializeSolutionStep(self, process_info: ProcessInfo) -> None:
        """
        Called at the start of each step.
        """
    def IsPaired(self) -> bool:
        """
        True for contact, mesh-tying and MPC pair conditions.
        """
    def Load(self, data: bytes) -> None:
        """
        Restores the state written by Save() of a condition of the same class; InputError otherwise.
        """
    def Save(self) -> bytes:
        """
        The restart state of the condition (id, flags and, for pairs, the master normal and the frictional start-of-step operators) as bytes.
        """
    @typing.overload
    def SetValue(self, variable: BoolVariable, value: bool) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: IntegerVariable, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: DoubleVariable, value: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: Array1DVariable3, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: VectorVariable, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: MatrixVariable, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: StringVariable, value: str) -> None:
        """
        Stores a value for the variable.
        """
    def __eq__(self, arg0: Condition) -> bool:
        """
        Same C++ object.
        """
    def __hash__(self) -> int:
        """
        Hash of the address.
        """
    def __repr__(self) -> str:
        """
        <Info()>.
        """
    @property
    def Id(self) -> int:
        """
        Id.
        """
    @property
    def Properties(self) -> Properties:
        """
        The properties (None if unset).
        """
    @Properties.setter
    def Properties(self, arg1: Properties) -> None:
        ...
class MasterSlaveConstraint(Flags):
    """
    A multipoint constraint u_slave = T u_master + c (Kratos MasterSlaveConstraint).
    """
    def Apply(self, process_info: ProcessInfo) -> None:
        """
        Sets the slave values to T u_master + c.
        """
    def CalculateLocalSystem(self, process_info: ProcessInfo) -> tuple[typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"], typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]]:
        """
        (T, c): relation (slaves x masters) and constant.
        """
    def Check(self, process_info: ProcessInfo) -> int:
        """
        0, or InputError naming what is missing.
        """
    def EquationIdVector(self, process_info: ProcessInfo) -> tuple[list[int], list[int]]:
        """
        (slave equation ids, master equation ids).
        """
    def FinalizeNonLinearIteration(self, process_info: ProcessInfo) -> None:
        """
        Called after each non-linear iteration.
        """
    def FinalizeSolutionStep(self, process_info: ProcessInfo) -> None:
        """
        Called at the end of each step.
        """
    def GetDofList(self, process_info: ProcessInfo) -> tuple[list, list]:
        """
        (slave DoFs, master DoFs).
        """
    def GetMasterDofsVector(self) -> list:
        """
        The master DoFs.
        """
    def GetSlaveDofsVector(self) -> list:
        """
        The slave DoFs.
        """
    @typing.overload
    def GetValue(self, variable: BoolVariable) -> bool:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: IntegerVariable) -> int:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: DoubleVariable) -> float:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: Array1DVariable3) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: VectorVariable) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: MatrixVariable) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: StringVariable) -> str:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: VariableData) -> None:
        """
        Pointer variables cannot be read from Python.
        """
    def Has(self, variable: VariableData) -> bool:
        """
        True if a value is stored for the variable.
        """
    def Info(self) -> str:
        """
        Short description.
        """
    def Initialize(self, process_info: ProcessInfo) -> None:
        """
        Called once before the analysis.
        """
    def InitializeNonLinearIteration(self, process_info: ProcessInfo) -> None:
        """
        Called before each non-linear iteration.
        """
    def InitializeSolutionStep(self, process_info: ProcessInfo) -> None:
        """
        Called at the start of each step.
        """
    @typing.overload
    def SetValue(self, variable: BoolVariable, value: bool) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: IntegerVariable, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: DoubleVariable, value: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: Array1DVariable3, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: VectorVariable, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: MatrixVariable, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: StringVariable, value: str) -> None:
        """
        Stores a value for the variable.
        """
    def __eq__(self, arg0: MasterSlaveConstraint) -> bool:
        """
        Same C++ object.
        """
    def __hash__(self) -> int:
        """
        Hash of the address.
        """
    def __repr__(self) -> str:
        """
        <Info()>.
        """
    @property
    def Id(self) -> int:
        """
        Id.
        """
class NodesArrayIterator:
    """
    Iterator over a model part container, in id order.
    """
    def __iter__(self) -> typing.Any:
        """
        The iterator itself.
        """
    def __next__(self) -> Node:
        """
        The next entity.
        """
class NodesArray:
    """
    Read-only container of a model part: len(), iteration in id order, `in`.
    """
    @typing.overload
    def __contains__(self, id: typing.SupportsInt | typing.SupportsIndex) -> bool:
        """
        True if an entity with this id is present.
        """
    @typing.overload
    def __contains__(self, entity: Node) -> bool:
        """
        True if this entity is present.
        """
    def __iter__(self) -> NodesArrayIterator:
        """
        Iterates in id order.
        """
    def __len__(self) -> int:
        """
        Number of entities.
        """
    def __repr__(self) -> str:
        """
        <NodesArray of n>.
        """
class ElementsArrayIterator:
    """
    Iterator over a model part container, in id order.
    """
    def __iter__(self) -> typing.Any:
        """
        The iterator itself.
        """
    def __next__(self) -> Element:
        """
        The next entity.
        """
class ElementsArray:
    """
    Read-only container of a model part: len(), iteration in id order, `in`.
    """
    @typing.overload
    def __contains__(self, id: typing.SupportsInt | typing.SupportsIndex) -> bool:
        """
        True if an entity with this id is present.
        """
    @typing.overload
    def __contains__(self, entity: Element) -> bool:
        """
        True if this entity is present.
        """
    def __iter__(self) -> ElementsArrayIterator:
        """
        Iterates in id order.
        """
    def __len__(self) -> int:
        """
        Number of entities.
        """
    def __repr__(self) -> str:
        """
        <NodesArray of n>.
        """
class ConditionsArrayIterator:
    """
    Iterator over a model part container, in id order.
    """
    def __iter__(self) -> typing.Any:
        """
        The iterator itself.
        """
    def __next__(self) -> Condition:
        """
        The next entity.
        """
class ConditionsArray:
    """
    Read-only container of a model part: len(), iteration in id order, `in`.
    """
    @typing.overload
    def __contains__(self, id: typing.SupportsInt | typing.SupportsIndex) -> bool:
        """
        True if an entity with this id is present.
        """
    @typing.overload
    def __contains__(self, entity: Condition) -> bool:
        """
        True if this entity is present.
        """
    def __iter__(self) -> ConditionsArrayIterator:
        """
        Iterates in id order.
        """
    def __len__(self) -> int:
        """
        Number of entities.
        """
    def __repr__(self) -> str:
        """
        <NodesArray of n>.
        """
class MasterSlaveConstraintsArrayIterator:
    """
    Iterator over a model part container, in id order.
    """
    def __iter__(self) -> typing.Any:
        """
        The iterator itself.
        """
    def __next__(self) -> MasterSlaveConstraint:
        """
        The next entity.
        """
class MasterSlaveConstraintsArray:
    """
    Read-only container of a model part: len(), iteration in id order, `in`.
    """
    @typing.overload
    def __contains__(self, id: typing.SupportsInt | typing.SupportsIndex) -> bool:
        """
        True if an entity with this id is present.
        """
    @typing.overload
    def __contains__(self, entity: MasterSlaveConstraint) -> bool:
        """
        True if this entity is present.
        """
    def __iter__(self) -> MasterSlaveConstraintsArrayIterator:
        """
        Iterates in id order.
        """
    def __len__(self) -> int:
        """
        Number of entities.
        """
    def __repr__(self) -> str:
        """
        <NodesArray of n>.
        """
class PropertiesArrayIterator:
    """
    Iterator over a model part container, in id order.
    """
    def __iter__(self) -> typing.Any:
        """
        The iterator itself.
        """
    def __next__(self) -> Properties:
        """
        The next entity.
        """
class PropertiesArray:
    """
    Read-only container of a model part: len(), iteration in id order, `in`.
    """
    @typing.overload
    def __contains__(self, id: typing.SupportsInt | typing.SupportsIndex) -> bool:
        """
        True if an entity with this id is present.
        """
    @typing.overload
    def __contains__(self, entity: Properties) -> bool:
        """
        True if this entity is present.
        """
    def __iter__(self) -> PropertiesArrayIterator:
        """
        Iterates in id order.
        """
    def __len__(self) -> int:
        """
        Number of entities.
        """
    def __repr__(self) -> str:
        """
        <NodesArray of n>.
        """
class Model:
    """
    Owner of the root model parts (Kratos Model).
    """
    def CreateModelPart(self, name: str, buffer_size: typing.SupportsInt | typing.SupportsIndex = 1) -> ModelPart:
        """
        A new root model part (dotted names create sub model parts).
        """
    def DeleteModelPart(self, name: str) -> None:
        """
        Deletes a model part (Python references to it become invalid).
        """
    def GetModelPart(self, name: str) -> ModelPart:
        """
        A model part by name or dotted path.
        """
    def GetModelPartNames(self) -> list[str]:
        """
        Sorted names of the root model parts.
        """
    def HasModelPart(self, name: str) -> bool:
        """
        True if the model part exists.
        """
    def __contains__(self, name: str) -> bool:
        """
        Same as HasModelPart(name).
        """
    def __getitem__(self, name: str) -> ModelPart:
        """
        Same as GetModelPart(name).
        """
    def __init__(self) -> None:
        """
        An empty model.
        """
    def __repr__(self) -> str:
        """
        <Model [names]>.
        """
class ModelPart(Flags):
    """
    A named set of nodes, elements, conditions and properties (Kratos ModelPart).
    """
    def AddCondition(self, condition: Condition) -> None:
        """
        Adds a condition of the same root.
        """
    def AddConditions(self, ids: collections.abc.Sequence[typing.SupportsInt | typing.SupportsIndex]) -> None:
        """
        Adds root conditions by id.
        """
    def AddElement(self, element: Element) -> None:
        """
        Adds an element of the same root.
        """
    def AddElements(self, ids: collections.abc.Sequence[typing.SupportsInt | typing.SupportsIndex]) -> None:
        """
        Adds root elements by id.
        """
    def AddGeometry(self, id: typing.SupportsInt | typing.SupportsIndex, geometry: Geometry) -> None:
        """
        Adds a geometry.
        """
    def AddMasterSlaveConstraint(self, constraint: MasterSlaveConstraint) -> None:
        """
        Adds a constraint.
        """
    def AddMasterSlaveConstraints(self, ids: collections.abc.Sequence[typing.SupportsInt | typing.SupportsIndex]) -> None:
        """
        Adds root constraints by id.
        """
    def AddNodalSolutionStepVariable(self, variable: VariableData) -> None:
        """
        Declares a historical variable (before nodes are created).
        """
    def AddNode(self, node: Node) -> None:
        """
        Adds a node of the same root.
        """
    def AddNodes(self, ids: collections.abc.Sequence[typing.SupportsInt | typing.SupportsIndex]) -> None:
        """
        Adds root nodes by id.
        """
    def AddProperties(self, properties: Properties) -> None:
        """
        Adds properties.
        """
    def AddTable(self, id: typing.SupportsInt | typing.SupportsIndex, table: Table) -> None:
        """
        Adds a table.
        """
    def CloneTimeStep(self, time: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        Shifts the buffers; sets TIME, DELTA_TIME, STEP.
        """
    def CreateNewCondition(self, name: str, id: typing.SupportsInt | typing.SupportsIndex, node_ids: collections.abc.Sequence[typing.SupportsInt | typing.SupportsIndex], properties: Properties) -> Condition:
        """
        A registered condition on root nodes.
        """
    def CreateNewElement(self, name: str, id: typing.SupportsInt | typing.SupportsIndex, node_ids: collections.abc.Sequence[typing.SupportsInt | typing.SupportsIndex], properties: Properties) -> Element:
        """
        A registered element on root nodes.
        """
    @typing.overload
    def CreateNewMasterSlaveConstraint(self, name: str, id: typing.SupportsInt | typing.SupportsIndex, master_dofs: collections.abc.Sequence[Dof], slave_dofs: collections.abc.Sequence[Dof], relation: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"], constant: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> MasterSlaveConstraint:
        """
        A registered constraint: slaves = relation @ masters + constant.
        """
    @typing.overload
    def CreateNewMasterSlaveConstraint(self, name: str, id: typing.SupportsInt | typing.SupportsIndex, master_node: Node, master_variable: DoubleVariable, slave_node: Node, slave_variable: DoubleVariable, weight: typing.SupportsFloat | typing.SupportsIndex, constant: typing.SupportsFloat | typing.SupportsIndex) -> MasterSlaveConstraint:
        """
        slave = weight * master + constant.
        """
    def CreateNewNode(self, id: typing.SupportsInt | typing.SupportsIndex, x: typing.SupportsFloat | typing.SupportsIndex, y: typing.SupportsFloat | typing.SupportsIndex, z: typing.SupportsFloat | typing.SupportsIndex) -> Node:
        """
        A new node (ids are unique per root).
        """
    def CreateNewPairedCondition(self, name: str, id: typing.SupportsInt | typing.SupportsIndex, slave_node_ids: collections.abc.Sequence[typing.SupportsInt | typing.SupportsIndex], master_node_ids: collections.abc.Sequence[typing.SupportsInt | typing.SupportsIndex], properties: Properties) -> Condition:
        """
        A paired (contact / mesh-tying / MPC) condition over a slave and a master face.
        """
    def CreateNewProperties(self, id: typing.SupportsInt | typing.SupportsIndex) -> Properties:
        """
        New properties.
        """
    def CreateSubModelPart(self, name: str) -> ModelPart:
        """
        A new sub model part.
        """
    def FullName(self) -> str:
        """
        Dotted path from the root, e.g. "Structure.Contact_Part".
        """
    def GetBufferSize(self) -> int:
        """
        Number of historical steps kept.
        """
    def GetCondition(self, id: typing.SupportsInt | typing.SupportsIndex) -> Condition:
        """
        The condition; InputError if missing.
        """
    def GetElement(self, id: typing.SupportsInt | typing.SupportsIndex) -> Element:
        """
        The element; InputError if missing.
        """
    def GetGeometry(self, id: typing.SupportsInt | typing.SupportsIndex) -> Geometry:
        """
        The geometry; InputError if missing.
        """
    def GetMasterSlaveConstraint(self, id: typing.SupportsInt | typing.SupportsIndex) -> MasterSlaveConstraint:
        """
        The constraint; InputError if missing.
        """
    def GetModel(self) -> Model:
        """
        The owning Model (None if stand-alone).
        """
    def GetNode(self, id: typing.SupportsInt | typing.SupportsIndex) -> Node:
        """
        The node; InputError if missing.
        """
    def GetParentModelPart(self) -> ModelPart:
        """
        The parent (itself for a root).
        """
    def GetProperties(self, id: typing.SupportsInt | typing.SupportsIndex) -> Properties:
        """
        The properties (created if missing, as Kratos).
        """
    def GetRootModelPart(self) -> ModelPart:
        """
        The root of the hierarchy.
        """
    def GetSubModelPart(self, name: str) -> ModelPart:
        """
        A sub model part by name or dotted path "A.B".
        """
    def GetSubModelPartNames(self) -> list[str]:
        """
        Names of the direct sub model parts.
        """
    def GetTable(self, id: typing.SupportsInt | typing.SupportsIndex) -> Table:
        """
        The table; InputError if missing.
        """
    @typing.overload
    def GetValue(self, variable: BoolVariable) -> bool:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: IntegerVariable) -> int:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: DoubleVariable) -> float:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: Array1DVariable3) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: VectorVariable) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: MatrixVariable) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: StringVariable) -> str:
        """
        Stored value of the variable (its zero when unset).
        """
    @typing.overload
    def GetValue(self, variable: VariableData) -> None:
        """
        Pointer variables cannot be read from Python.
        """
    def Has(self, variable: VariableData) -> bool:
        """
        True if a value is stored for the variable.
        """
    def HasCondition(self, id: typing.SupportsInt | typing.SupportsIndex) -> bool:
        """
        True if the condition is here.
        """
    def HasElement(self, id: typing.SupportsInt | typing.SupportsIndex) -> bool:
        """
        True if the element is here.
        """
    def HasGeometry(self, id: typing.SupportsInt | typing.SupportsIndex) -> bool:
        """
        True if the geometry exists.
        """
    def HasMasterSlaveConstraint(self, id: typing.SupportsInt | typing.SupportsIndex) -> bool:
        """
        True if the constraint is here.
        """
    def HasNodalSolutionStepVariable(self, variable: VariableData) -> bool:
        """
        True if the variable is historical.
        """
    def HasNode(self, id: typing.SupportsInt | typing.SupportsIndex) -> bool:
        """
        True if the node is here.
        """
    def HasProperties(self, id: typing.SupportsInt | typing.SupportsIndex) -> bool:
        """
        True if the properties exist here.
        """
    def HasSubModelPart(self, name: str) -> bool:
        """
        True if the sub model part exists.
        """
    def HasTable(self, id: typing.SupportsInt | typing.SupportsIndex) -> bool:
        """
        True if the table exists.
        """
    def Info(self) -> str:
        """
        Multi-line summary of the hierarchy.
        """
    def IsSubModelPart(self) -> bool:
        """
        True unless this is a root model part.
        """
    def NumberOfConditions(self) -> int:
        """
        Number of conditions.
        """
    def NumberOfElements(self) -> int:
        """
        Number of elements.
        """
    def NumberOfGeometries(self) -> int:
        """
        Number of geometries.
        """
    def NumberOfMasterSlaveConstraints(self) -> int:
        """
        Number of constraints.
        """
    def NumberOfNodes(self) -> int:
        """
        Number of nodes.
        """
    def NumberOfProperties(self) -> int:
        """
        Number of properties.
        """
    def NumberOfSubModelParts(self) -> int:
        """
        Number of direct sub model parts.
        """
    def NumberOfTables(self) -> int:
        """
        Number of tables.
        """
    def RemoveCondition(self, id: typing.SupportsInt | typing.SupportsIndex) -> None:
        """
        Removes the condition here and below.
        """
    def RemoveConditionsFlagged(self, flag: Flags) -> int:
        """
        Removes the conditions with flag set; returns how many.
        """
    def RemoveElement(self, id: typing.SupportsInt | typing.SupportsIndex) -> None:
        """
        Removes the element here and below.
        """
    def RemoveMasterSlaveConstraint(self, id: typing.SupportsInt | typing.SupportsIndex) -> None:
        """
        Removes the constraint.
        """
    def RemoveNode(self, id: typing.SupportsInt | typing.SupportsIndex) -> None:
        """
        Removes the node here and below.
        """
    def RemoveNodeFromAllLevels(self, id: typing.SupportsInt | typing.SupportsIndex) -> None:
        """
        Removes the node everywhere.
        """
    def RemoveSubModelPart(self, name: str) -> None:
        """
        Deletes a sub model part.
        """
    def SetBufferSize(self, buffer_size: typing.SupportsInt | typing.SupportsIndex) -> None:
        """
        Number of historical steps kept.
        """
    @typing.overload
    def SetValue(self, variable: BoolVariable, value: bool) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: IntegerVariable, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: DoubleVariable, value: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: Array1DVariable3, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: VectorVariable, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: MatrixVariable, value: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, n]"]) -> None:
        """
        Stores a value for the variable.
        """
    @typing.overload
    def SetValue(self, variable: StringVariable, value: str) -> None:
        """
        Stores a value for the variable.
        """
    def __eq__(self, arg0: ModelPart) -> bool:
        """
        Same C++ object.
        """
    def __hash__(self) -> int:
        """
        Hash of the address.
        """
    def __repr__(self) -> str:
        """
        <ModelPart Full.Name>.
        """
    def __str__(self) -> str:
        """
        Same as Info().
        """
    @property
    def Conditions(self) -> ConditionsArray:
        """
        The conditions (ConditionsArray).
        """
    @property
    def Elements(self) -> ElementsArray:
        """
        The elements (ElementsArray).
        """
    @property
    def MasterSlaveConstraints(self) -> MasterSlaveConstraintsArray:
        """
        The constraints (MasterSlaveConstraintsArray).
        """
    @property
    def Name(self) -> str:
        """
        Name (without the parents).
        """
    @property
    def Nodes(self) -> NodesArray:
        """
        The nodes (NodesArray).
        """
    @property
    def ProcessInfo(self) -> ProcessInfo:
        """
        The ProcessInfo shared by the hierarchy.
        """
    @property
    def Properties(self) -> PropertiesArray:
        """
        The properties (PropertiesArray).
        """
    @property
    def SubModelParts(self) -> list:
        """
        The direct sub model parts.
        """
class ModelPartIO:
    """
    Reader of Kratos .mdpa files (Kratos ModelPartIO, read side).
    """
    def FileName(self) -> str:
        """
        The resolved path of the file.
        """
    def ReadModelPart(self, model_part: ModelPart) -> None:
        """
        Reads the whole file into model_part; InputError on bad content.
        """
    def __init__(self, filename: str) -> None:
        """
        Reader of filename, with or without the .mdpa extension.
        """
class VariableUtils:
    """
    Nodal helpers (Kratos VariableUtils).
    """
    def CopySolutionStepData(self, model_part: ModelPart, source: typing.SupportsInt | typing.SupportsIndex, destination: typing.SupportsInt | typing.SupportsIndex) -> None:
        """
        Copies every historical value of buffer step source into step destination on the nodes of model_part (restarting a step from the last converged state: source 1, destination 0).
        """
    @typing.overload
    def SetFlag(self, flag: Flags, value: bool, entities: NodesArray) -> None:
        """
        Sets flag to value on every node of a model part's Nodes (looped in C++).
        """
    @typing.overload
    def SetFlag(self, flag: Flags, value: bool, entities: ConditionsArray) -> None:
        """
        Sets flag to value on every condition of a model part's Conditions (looped in C++).
        """
    @typing.overload
    def SetFlag(self, flag: Flags, value: bool, entities: ElementsArray) -> None:
        """
        Sets flag to value on every element of a model part's Elements (looped in C++).
        """
    @typing.overload
    def SetFlag(self, flag: Flags, value: bool, entities: collections.abc.Iterable) -> None:
        """
        Sets flag to value on every node / element / condition of the iterable.
        """
    def UpdateCurrentPosition(self, nodes: collections.abc.Iterable, variable: Array1DVariable3 = ..., buffer_step: typing.SupportsInt | typing.SupportsIndex = 0) -> None:
        """
        Current coordinates = initial + historical variable (DISPLACEMENT) for every node of the iterable.
        """
    def __init__(self) -> None:
        """
        The helpers.
        """
class LinearSolver:
    """
    Solver of the global linear system.
    """
    def Clear(self) -> None:
        """
        Forgets the cached factorisation.
        """
    def GetStatistics(self) -> dict:
        """
        solver, ordering (used) and ordering_setting (asked for), factorizations, system_size, factor_nonzeros (nnz L + U) and factor_memory (bytes) of the last factorisation, and their maxima; factor_flops, symbolic_seconds and numeric_seconds (CPU) summed over the run, symbolic_analyses, workspace_enlargements (MUMPS factorisations redone with more working space), out_of_core_factorizations (MUMPS factorisations kept on disk); static condensation: condensation ('' = not a condensing solver, 'yes' or 'no (why)'), interface_size and bulk_size of the last condensed solve, bulk_factorizations, condensed_solves, bulk_seconds and interface_seconds (wall); Krylov solvers: krylov (True), krylov_method, krylov_iterations (per solve of the run), last_relative_residual, tolerance, preconditioner_seconds, preconditioner_setups (solves that set the preconditioner up), krylov_seconds (wall), ranks (MPI) and near_null_space (rigid-body modes given).
        """
    def Info(self) -> str:
        """
        The solver's own name (umfpack, mumps, cholmod, klu, sparse_lu, cg, bicgstab; under a Kratos LU name, the one that ran last).
        """
    def NumberOfSymbolicAnalyses(self) -> int:
        """
        How often the sparsity pattern was analysed (pattern reuse diagnostic).
        """
class StaticCondensationSolver(LinearSolver):
    """
    Condenses a constant bulk onto the contact interface (linear_solver_settings.static_condensation).
    """
    def InnerSolver(self) -> LinearSolver:
        """
        The solver of the full system.
        """
    def LastSolveWasCondensed(self) -> bool:
        ...
    def SetBulkInCoreLimit(self, bytes: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        Bulk factors CHOLMOD expects above this many bytes are kept out of core by MUMPS instead (0: always; negative, the default: half the memory available when the bulk is factorised).
        """
    def __init__(self, inner: LinearSolver, mode: str = 'auto', bulk_not_linear: str = '') -> None:
        """
        inner: solver of the full system; mode: 'auto', 'on' or 'off'; bulk_not_linear: why the bodies' stiffness may change ('' = it does not; 'auto' then refuses).
        """
class ResidualBasedIncrementalUpdateStaticScheme:
    """
    Static scheme (base of all schemes): u += Δx on free DoFs.
    """
    def Check(self, model_part: ModelPart) -> int:
        ...
    def Info(self) -> str:
        """
        Scheme name.
        """
    def __init__(self) -> None:
        ...
class ResidualBasedBossakDisplacementScheme(ResidualBasedIncrementalUpdateStaticScheme):
    """
    Implicit Bossak–Newmark displacement scheme.
    """
    def __init__(self, damp_factor_m: typing.SupportsFloat | typing.SupportsIndex = -0.3, newmark_beta: typing.SupportsFloat | typing.SupportsIndex = 0.25) -> None:
        ...
class BuilderAndSolver:
    """
    Global assembly and solve.
    """
    def GetDofSet(self) -> list[Dof]:
        """
        The DoFs of the system, sorted by (node id, variable).
        """
    def GetEquationSystemSize(self) -> int:
        """
        Number of equations.
        """
    def GetTimings(self) -> dict:
        """
        Seconds spent in setup (DoFs, graph), build (assembly) and solve, and the call counts.
        """
    def Info(self) -> str:
        """
        block or elimination.
        """
    def ResetTimings(self) -> None:
        ...
class ResidualBasedBlockBuilderAndSolver(BuilderAndSolver):
    """
    Builder keeping fixed DoFs in the system.
    """
    def __init__(self, linear_solver: LinearSolver) -> None:
        ...
class ResidualBasedEliminationBuilderAndSolver(BuilderAndSolver):
    """
    Builder removing fixed DoFs from the system.
    """
    def __init__(self, linear_solver: LinearSolver) -> None:
        ...
class ConvergenceCriteria:
    """
    Newton convergence test.
    """
    def Info(self) -> str:
        """
        Criterion name.
        """
    def LastNorms(self) -> str:
        """
        The norms of the last check, one line.
        """
    def SetEchoLevel(self, level: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
class DisplacementCriteria(ConvergenceCriteria):
    """
    Relative/absolute norm of the free DoF increment.
    """
    def LastAbsolute(self) -> float:
        ...
    def LastRatio(self) -> float:
        ...
    def __init__(self, relative_tolerance: typing.SupportsFloat | typing.SupportsIndex, absolute_tolerance: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class ResidualCriteria(ConvergenceCriteria):
    """
    Relative/absolute norm of the free, unconstrained residual.
    """
    def LastAbsolute(self) -> float:
        ...
    def LastRatio(self) -> float:
        ...
    def __init__(self, relative_tolerance: typing.SupportsFloat | typing.SupportsIndex, absolute_tolerance: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class MixedGenericCriteria(ConvergenceCriteria):
    """
    Increment criterion with (relative, absolute) tolerances per variable.
    """
    def LastAbsolute(self, group: typing.SupportsInt | typing.SupportsIndex) -> float:
        ...
    def LastRatio(self, group: typing.SupportsInt | typing.SupportsIndex) -> float:
        ...
    def __init__(self, tolerances: collections.abc.Sequence[tuple[VariableData, typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex]]) -> None:
        """
        tolerances: list of (variable, relative_tolerance, absolute_tolerance).
        """
class CompositeCriteria(ConvergenceCriteria):
    """
    Two criteria combined with AND or OR.
    """
class SolvingStrategy:
    """
    Implicit solving strategy.
    """
    def Check(self) -> int:
        ...
    def Clear(self) -> None:
        ...
    def FinalizeSolutionStep(self) -> None:
        ...
    def GetBuilderAndSolver(self) -> BuilderAndSolver:
        ...
    def GetIterationNumber(self) -> int:
        ...
    def GetSolutionVector(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        Copy of the last increment Δx.
        """
    def GetSystemVector(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        Copy of the last right-hand side.
        """
    def Initialize(self) -> None:
        ...
    def InitializeSolutionStep(self) -> None:
        ...
    def IsConverged(self) -> bool:
        ...
    def MoveMesh(self) -> None:
        ...
    def Predict(self) -> None:
        ...
    def SetEchoLevel(self, level: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def SetIterationObserver(self, observer: collections.abc.Callable[[], None] | None) -> None:
        """
        Callable without arguments run after every Newton iteration (None removes it); an exception it raises ends the step.
        """
    def Solve(self) -> bool:
        """
        The four step calls in order; returns convergence.
        """
    def SolveSolutionStep(self) -> bool:
        """
        Returns whether the step converged.
        """
class ResidualBasedNewtonRaphsonStrategy(SolvingStrategy):
    """
    Full Newton–Raphson (LHS rebuilt every iteration).
    """
    def CheckTangentAlong(self, direction: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"] | None = None, step: typing.SupportsFloat | typing.SupportsIndex = 1e-07) -> tuple[typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"], typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"], typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]]:
        """
        (A v, −(b(x+hv) − b(x−hv))/2h, v) at the current iterate, fixed DoFs zero; direction None: the Newton correction. A developer's check of the assembled tangent (docs/theory/structural.md §6).
        """
    def GetMaxIterationNumber(self) -> int:
        ...
    def IterationHistory(self) -> list[str]:
        """
        Criterion norms per iteration of the last step.
        """
    def SetMaxIterationNumber(self, max_iteration: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __init__(self, model_part: ModelPart, scheme: ResidualBasedIncrementalUpdateStaticScheme, convergence_criterion: ConvergenceCriteria, builder_and_solver: BuilderAndSolver, max_iteration: typing.SupportsInt | typing.SupportsIndex = 10, compute_reactions: bool = True, reform_step_dofs: bool = False, move_mesh_flag: bool = True) -> None:
        ...
class LineSearchStrategy(ResidualBasedNewtonRaphsonStrategy):
    """
    Newton–Raphson with a secant line search.
    """
    def LastAlpha(self) -> float:
        ...
    def __init__(self, model_part: ModelPart, scheme: ResidualBasedIncrementalUpdateStaticScheme, convergence_criterion: ConvergenceCriteria, builder_and_solver: BuilderAndSolver, max_iteration: typing.SupportsInt | typing.SupportsIndex = 10, compute_reactions: bool = True, reform_step_dofs: bool = False, move_mesh_flag: bool = True, max_line_search_iterations: typing.SupportsInt | typing.SupportsIndex = 5, first_alpha_value: typing.SupportsFloat | typing.SupportsIndex = 0.5, second_alpha_value: typing.SupportsFloat | typing.SupportsIndex = 1.0, min_alpha: typing.SupportsFloat | typing.SupportsIndex = 0.1, max_alpha: typing.SupportsFloat | typing.SupportsIndex = 2.0, line_search_tolerance: typing.SupportsFloat | typing.SupportsIndex = 0.5) -> None:
        ...
class InterfacePreprocessCondition:
    """
    Builds interface (skin) conditions from the elements of the main model part.
    """
    def GenerateInterfacePart(self, model_part: ModelPart, simplify_geometry: bool = False, contact_property_id: typing.SupportsInt | typing.SupportsIndex = 0) -> int:
        """
        Creates the boundary-face conditions over the part's nodes; returns how many were created.
        """
    def GenerateSkin(self, destination_model_part: ModelPart, contact_property_id: typing.SupportsInt | typing.SupportsIndex = 0) -> int:
        """
        Alias of GenerateSkinModelPart.
        """
    def GenerateSkinModelPart(self, destination_model_part: ModelPart, contact_property_id: typing.SupportsInt | typing.SupportsIndex = 0) -> int:
        """
        Skin of the whole main model part into the destination sub model part; returns the count.
        """
    def __init__(self, main_model_part: ModelPart) -> None:
        ...
class FindNodalHProcess:
    """
    NODAL_H = shortest element edge around each node.
    """
    def Execute(self) -> None:
        """
        Runs the process.
        """
    def ExecuteAfterOutputStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteBeforeOutputStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteBeforeSolutionLoop(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteFinalize(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteFinalizeSolutionStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteInitialize(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteInitializeSolutionStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def __init__(self, model_part: ModelPart) -> None:
        ...
class NormalCheckProcess:
    """
    Flips interface conditions whose normal points inwards.
    """
    def Execute(self) -> None:
        """
        Runs the process.
        """
    def ExecuteAfterOutputStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteBeforeOutputStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteBeforeSolutionLoop(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteFinalize(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteFinalizeSolutionStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteInitialize(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteInitializeSolutionStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def NumberOfFlippedConditions(self) -> int:
        """
        How many conditions the last Execute() flipped.
        """
    def __init__(self, model_part: ModelPart, length_proportion: typing.SupportsFloat | typing.SupportsIndex = 0.1, check_threshold: typing.SupportsFloat | typing.SupportsIndex = 5e-07) -> None:
        ...
class MasterSlaveProcess:
    """
    SLAVE / MASTER flags of conditions from their nodes.
    """
    def Execute(self) -> None:
        """
        Runs the process.
        """
    def ExecuteAfterOutputStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteBeforeOutputStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteBeforeSolutionLoop(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteFinalize(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteFinalizeSolutionStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteInitialize(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteInitializeSolutionStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def __init__(self, model_part: ModelPart) -> None:
        ...
class ALMVariablesCalculationProcess:
    """
    ProcessInfo INITIAL_PENALTY and SCALE_FACTOR from the interface stiffness.
    """
    def Execute(self) -> None:
        """
        Runs the process.
        """
    def ExecuteAfterOutputStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteBeforeOutputStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteBeforeSolutionLoop(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteFinalize(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteFinalizeSolutionStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteInitialize(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteInitializeSolutionStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def __init__(self, model_part: ModelPart, stiffness_factor: typing.SupportsFloat | typing.SupportsIndex = 1.0, penalty_scale_factor: typing.SupportsFloat | typing.SupportsIndex = 1.0) -> None:
        ...
class ALMFastInit:
    """
    Initial nodal contact values (penalty, gaps, friction coefficients).
    """
    def Execute(self) -> None:
        """
        Runs the process.
        """
    def ExecuteAfterOutputStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteBeforeOutputStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteBeforeSolutionLoop(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteFinalize(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteFinalizeSolutionStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteInitialize(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteInitializeSolutionStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def __init__(self, model_part: ModelPart) -> None:
        ...
class AALMAdaptPenaltyValueProcess:
    """
    Adaptive nodal ALM penalty.
    """
    def Execute(self) -> None:
        """
        Runs the process.
        """
    def ExecuteAfterOutputStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteBeforeOutputStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteBeforeSolutionLoop(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteFinalize(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteFinalizeSolutionStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteInitialize(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteInitializeSolutionStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def __init__(self, model_part: ModelPart) -> None:
        ...
class ComputeDynamicFactorProcess:
    """
    DYNAMIC_FACTOR: share of the step after impact.
    """
    def Execute(self) -> None:
        """
        Runs the process.
        """
    def ExecuteAfterOutputStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteBeforeOutputStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteBeforeSolutionLoop(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteFinalize(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteFinalizeSolutionStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteInitialize(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def ExecuteInitializeSolutionStep(self) -> None:
        """
        No-op (Kratos Process hook).
        """
    def __init__(self, model_part: ModelPart) -> None:
        ...
class ContactUtilities:
    """
    Model-part helpers of the contact workflow (static).
    """
    @staticmethod
    def ActivateConditionWithActiveNodes(model_part: ModelPart) -> None:
        ...
    @staticmethod
    def CalculateMaxNodalH(model_part: ModelPart) -> float:
        ...
    @staticmethod
    def CalculateMeanNodalH(model_part: ModelPart) -> float:
        ...
    @staticmethod
    def CalculateMinimalNodalH(model_part: ModelPart) -> float:
        ...
    @staticmethod
    def CalculateRelativeSizeMesh(model_part: ModelPart) -> float:
        ...
    @staticmethod
    def CheckActivity(model_part: ModelPart, throw_error: bool = True) -> bool:
        ...
    @staticmethod
    def CheckModelPartHasRotationDoF(model_part: ModelPart) -> bool:
        ...
    @staticmethod
    def CleanContactModelParts(model_part: ModelPart) -> None:
        ...
    @staticmethod
    def ComputeExplicitContributionConditions(model_part: ModelPart) -> None:
        ...
    @staticmethod
    def ComputeStepJump(model_part: ModelPart, delta_time: typing.SupportsFloat | typing.SupportsIndex, half_step: bool = True) -> None:
        ...
    @staticmethod
    def DistancePoints(point_a: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"], point_b: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"]) -> float:
        ...
    @staticmethod
    def GetHalfJumpCenter(geometry: Geometry) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[3, 1]"]:
        ...
class ContactSearchSettings:
    """
    Settings of the contact search (Kratos search_parameters keys).
    """
    OBB_intersection_type: str
    build_from_bounding_box: bool
    condition_name: str
    consider_gap_threshold: bool
    debug_mode: bool
    debug_obb: bool
    dynamic_search: bool
    final_string: str
    id_name: str
    inverted_search: bool
    predefined_master_slave: bool
    predict_correct_lagrange_multiplier: bool
    pure_slip: bool
    simple_search: bool
    static_check_movement: bool
    @staticmethod
    def from_dict(values: dict, where: str = '') -> ContactSearchSettings:
        """
        Settings from a dict or a search_parameters block (max_number_results, octree_search_parameters); unknown keys, wrong types and values out of range raise InputError, located at where.
        """
    def Validate(self) -> None:
        """
        InputError for out-of-range values.
        """
    def __init__(self, **kwargs) -> None:
        """
        Defaults, overridden by keyword arguments (unknown keys raise InputError).
        """
    @property
    def allocation_size(self) -> int:
        ...
    @allocation_size.setter
    def allocation_size(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def bounding_box_factor(self) -> float:
        ...
    @bounding_box_factor.setter
    def bounding_box_factor(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def bucket_size(self) -> int:
        ...
    @bucket_size.setter
    def bucket_size(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def check_gap(self) -> str:
        """
        no_check, direct_check, check_mapping (or NoCheck, DirectCheck, MappingCheck).
        """
    @check_gap.setter
    def check_gap(self, arg1: str) -> None:
        ...
    @property
    def higher_bounding_box_coefficient(self) -> float:
        ...
    @higher_bounding_box_coefficient.setter
    def higher_bounding_box_coefficient(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def lower_bounding_box_coefficient(self) -> float:
        ...
    @lower_bounding_box_coefficient.setter
    def lower_bounding_box_coefficient(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def normal_orientation_threshold(self) -> float:
        ...
    @normal_orientation_threshold.setter
    def normal_orientation_threshold(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def search_factor(self) -> float:
        ...
    @search_factor.setter
    def search_factor(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def type_search(self) -> str:
        """
        in_radius, in_box, in_radius_with_obb, in_box_with_obb, octree_with_obb (or InRadius, ...).
        """
    @type_search.setter
    def type_search(self, arg1: str) -> None:
        ...
class ContactSearchProcess:
    """
    Mortar contact search (Kratos AdvancedContactSearchProcess; simple_search: SimpleContactSearchProcess).
    """
    def CheckContactModelParts(self) -> None:
        """
        Clone faces claimed by another search.
        """
    def ClearMortarConditions(self) -> None:
        """
        Erase inactive pairs, zero inactive multipliers.
        """
    def CreatePointListMortar(self) -> None:
        """
        Rebuild the master point list and tree.
        """
    def Execute(self) -> None:
        """
        The three phases in a row.
        """
    def ExecuteFinalizeSolutionStep(self) -> None:
        """
        ClearMortarConditions.
        """
    def ExecuteInitialize(self) -> None:
        """
        CheckContactModelParts, CreatePointListMortar, InitializeMortarConditions.
        """
    def ExecuteInitializeSolutionStep(self) -> None:
        """
        ClearMortarConditions + UpdateMortarConditions.
        """
    def GetComputingModelPart(self) -> ModelPart:
        ...
    def GetContactModelPart(self) -> ModelPart:
        ...
    def GetLastSearchTimings(self) -> dict:
        """
        Seconds spent in the last UpdateMortarConditions (tree_build, queries, total) and counts.
        """
    def GetPairs(self) -> list[tuple[int, int, int]]:
        """
        [(slave face id, master face id, pair condition id or 0)] from the INDEX_MAPs.
        """
    def InvertSearch(self) -> None:
        """
        Swap the slave and master roles.
        """
    def ResetContactOperators(self) -> None:
        """
        Erase inactive pairs (all if MODIFIED).
        """
    def UpdateMortarConditions(self) -> None:
        """
        The search of the step.
        """
    def __init__(self, main_model_part: ModelPart, settings: ContactSearchSettings, pair_properties: Properties = None, resume: bool = False) -> None:
        """
        Search over main_model_part.Contact[.ContactSub<id_name>]; pairs get pair_properties (None: the slave face's). resume: adopt the pairs and flags a restart file restored instead of erasing them.
        """
    @property
    def penetration_checked(self) -> bool:
        """
        Whether the first search's check for initially penetrating slave nodes ran (restart state).
        """
    @penetration_checked.setter
    def penetration_checked(self, arg1: bool) -> None:
        ...
    @property
    def settings(self) -> ContactSearchSettings:
        """
        The settings (a copy).
        """
class MPCContactSearchProcess(ContactSearchProcess):
    """
    Contact search that also creates a ContactMasterSlaveConstraint per pair.
    """
    def __init__(self, main_model_part: ModelPart, settings: ContactSearchSettings, pair_properties: Properties = None, resume: bool = False) -> None:
        """
        As ContactSearchProcess; ConfigurationError at the first pair if the constraint is not registered.
        """
class ContactBlockMeasure:
    """
    How a block of unknowns is judged converged.
    
    Members:
    
      INCREMENT
    
      RESIDUAL
    """
    INCREMENT: typing.ClassVar[ContactBlockMeasure]
    RESIDUAL: typing.ClassVar[ContactBlockMeasure]
    __members__: typing.ClassVar[dict[str, ContactBlockMeasure]]
    @typing.overload
    def __eq__(self, other: ContactBlockMeasure) -> bool:
        ...
    @typing.overload
    def __eq__(self, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self) -> int:
        ...
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __int__(self) -> int:
        ...
    @typing.overload
    def __ne__(self, other: ContactBlockMeasure) -> bool:
        ...
    @typing.overload
    def __ne__(self, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class ContactCriteriaTolerances:
    """
    Tolerances of the displacement and multiplier blocks of a contact system.
    """
    ensure_contact: bool
    pure_slip: bool
    split_frictional: bool
    def __init__(self) -> None:
        ...
    @property
    def displacement_absolute(self) -> float:
        ...
    @displacement_absolute.setter
    def displacement_absolute(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def displacement_relative(self) -> float:
        ...
    @displacement_relative.setter
    def displacement_relative(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def lm_absolute(self) -> float:
        ...
    @lm_absolute.setter
    def lm_absolute(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def lm_relative(self) -> float:
        ...
    @lm_relative.setter
    def lm_relative(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def ratio_normal_tangent_threshold(self) -> float:
        ...
    @ratio_normal_tangent_threshold.setter
    def ratio_normal_tangent_threshold(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def slip_absolute(self) -> float:
        ...
    @slip_absolute.setter
    def slip_absolute(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def slip_relative(self) -> float:
        ...
    @slip_relative.setter
    def slip_relative(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def stick_absolute(self) -> float:
        ...
    @stick_absolute.setter
    def stick_absolute(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def stick_relative(self) -> float:
        ...
    @stick_relative.setter
    def stick_relative(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class DisplacementLagrangeMultiplierContactCriteria(ConvergenceCriteria):
    """
    Block convergence (displacement / multiplier, optionally normal / stick / slip) of a mortar contact system.
    """
    def LastAbsolute(self, block: typing.SupportsInt | typing.SupportsIndex) -> float:
        """
        Absolute norm of block 0 disp, 1 lm (normal), 2 stick, 3 slip.
        """
    def LastRatio(self, block: typing.SupportsInt | typing.SupportsIndex) -> float:
        """
        Ratio of block 0 disp, 1 lm (normal), 2 stick, 3 slip.
        """
    def __init__(self, displacement_measure: ContactBlockMeasure, lm_measure: ContactBlockMeasure, tolerances: ContactCriteriaTolerances) -> None:
        ...
class BaseMortarConvergenceCriteria(ConvergenceCriteria):
    """
    Active-set (and stick/slip) convergence of a mortar contact formulation.
    """
    class Family:
        """
        Members:
        
          ALM_FRICTIONLESS
        
          ALM_FRICTIONLESS_COMPONENTS
        
          ALM_FRICTIONAL
        
          PENALTY_FRICTIONLESS
        
          PENALTY_FRICTIONAL
        
          MESH_TYING
        """
        ALM_FRICTIONAL: typing.ClassVar[BaseMortarConvergenceCriteria.Family]
        ALM_FRICTIONLESS: typing.ClassVar[BaseMortarConvergenceCriteria.Family]
        ALM_FRICTIONLESS_COMPONENTS: typing.ClassVar[BaseMortarConvergenceCriteria.Family]
        MESH_TYING: typing.ClassVar[BaseMortarConvergenceCriteria.Family]
        PENALTY_FRICTIONAL: typing.ClassVar[BaseMortarConvergenceCriteria.Family]
        PENALTY_FRICTIONLESS: typing.ClassVar[BaseMortarConvergenceCriteria.Family]
        __members__: typing.ClassVar[dict[str, BaseMortarConvergenceCriteria.Family]]
        @typing.overload
        def __eq__(self, other: BaseMortarConvergenceCriteria.Family) -> bool:
            ...
        @typing.overload
        def __eq__(self, other: typing.Any) -> bool:
            ...
        def __getstate__(self) -> int:
            ...
        def __hash__(self) -> int:
            ...
        def __index__(self) -> int:
            ...
        def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
            ...
        def __int__(self) -> int:
            ...
        @typing.overload
        def __ne__(self, other: BaseMortarConvergenceCriteria.Family) -> bool:
            ...
        @typing.overload
        def __ne__(self, other: typing.Any) -> bool:
            ...
        def __repr__(self) -> str:
            ...
        def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
            ...
        def __str__(self) -> str:
            ...
        @property
        def name(self) -> str:
            ...
        @property
        def value(self) -> int:
            ...
    def ActiveNodes(self) -> int:
        """
        Active slave nodes after the last update.
        """
    def LastActiveFlips(self) -> int:
        ...
    def LastSlipFlips(self) -> int:
        ...
    def NonDissipativeNodes(self) -> int:
        """
        ALM friction: slipping nodes of the last update whose traction points against the slip.
        """
    def SlipNodes(self) -> int:
        """
        Active slipping slave nodes after the last update.
        """
    def UpdateNormalsAndTangents(self, model_part: ModelPart) -> None:
        ...
    def __init__(self, family: BaseMortarConvergenceCriteria.Family, pure_slip: bool = False) -> None:
        ...
class MortarType:
    """
    A solver mortar_type decoded from the condition table: the condition family it runs, the variables and DoFs the solver adds, the mortar criterion.
    """
    def ConditionName(self, normal_variation: bool, axisymmetric: bool) -> str:
        """
        The condition name up to the pair, e.g. ALMNVFrictionalAxisymMortarContact.
        """
    @property
    def contact_type(self) -> str:
        """
        The contact process' contact_type; "" for tying.
        """
    @property
    def criterion(self) -> BaseMortarConvergenceCriteria.Family:
        """
        The family of its BaseMortarConvergenceCriteria.
        """
    @property
    def dofs(self) -> list[tuple[typing.Any, typing.Any]]:
        """
        (DoF, reaction) pairs the solver adds to every node.
        """
    @property
    def family(self) -> str:
        """
        Condition family: "Frictionless", "Frictional", ...
        """
    @property
    def frictional(self) -> bool:
        ...
    @property
    def has_axisym(self) -> bool:
        """
        The family has the 2D axisymmetric variant.
        """
    @property
    def method(self) -> str:
        """
        Condition name prefix: "ALM", "Penalty"; "" for mesh tying.
        """
    @property
    def multiplier(self) -> typing.Any:
        """
        The slave multiplier variable; None for the penalty families.
        """
    @property
    def name(self) -> str:
        ...
    @property
    def nodal_variables(self) -> list[typing.Any]:
        """
        Historical variables the solver adds to the structural ones, in order.
        """
    @property
    def pure_slip(self) -> bool:
        ...
class MixedULMLinearSolver(LinearSolver):
    """
    Condenses the dual multipliers of the active slave nodes and solves the displacement-sized system.
    """
    def LastCondensedMultipliers(self) -> int:
        ...
    def LastSolveWasCondensed(self) -> bool:
        ...
    def __init__(self, inner_solver: LinearSolver) -> None:
        ...
class ResidualBasedNewtonRaphsonContactStrategy(ResidualBasedNewtonRaphsonStrategy):
    """
    Newton–Raphson for mortar contact: explicit gaps after the prediction, active set updated by the criteria.
    """
    def GetInnerLoopIterations(self) -> int:
        ...
    def __init__(self, model_part: ModelPart, scheme: ResidualBasedIncrementalUpdateStaticScheme, convergence_criterion: ConvergenceCriteria, builder_and_solver: BuilderAndSolver, max_iteration: typing.SupportsInt | typing.SupportsIndex = 30, compute_reactions: bool = True, reform_step_dofs: bool = True, move_mesh_flag: bool = True, inner_loop_iterations: typing.SupportsInt | typing.SupportsIndex = 5) -> None:
        ...
class LineSearchContactStrategy(ResidualBasedNewtonRaphsonContactStrategy):
    """
    The contact Newton strategy with a line search per block (displacements, multipliers).
    """
    def LastDisplacementAlpha(self) -> float:
        ...
    def LastMultiplierAlpha(self) -> float:
        ...
    def __init__(self, model_part: ModelPart, scheme: ResidualBasedIncrementalUpdateStaticScheme, convergence_criterion: ConvergenceCriteria, builder_and_solver: BuilderAndSolver, max_iteration: typing.SupportsInt | typing.SupportsIndex = 30, compute_reactions: bool = True, reform_step_dofs: bool = True, move_mesh_flag: bool = True, inner_loop_iterations: typing.SupportsInt | typing.SupportsIndex = 5, min_alpha: typing.SupportsFloat | typing.SupportsIndex = 0.001) -> None:
        ...
class MPCContactCriteria(ConvergenceCriteria):
    """
    Active-set (and stick/slip) convergence of the MPC contact route from the reactions.
    """
    @staticmethod
    def ComputeLumpedSlaveArea(model_part: ModelPart) -> None:
        """
        NODAL_MAUX := lumped slave area on the nodes of "Contact".
        """
    def ActiveNodes(self) -> int:
        """
        Active slave nodes after the last update.
        """
    def LastActiveFlips(self) -> int:
        ...
    def LastSlipFlips(self) -> int:
        ...
    def SlipNodes(self) -> int:
        """
        Active slipping slave nodes after the last update.
        """
    def __init__(self) -> None:
        ...
class ResidualBasedNewtonRaphsonMPCContactStrategy(ResidualBasedNewtonRaphsonStrategy):
    """
    Newton–Raphson for MPC contact: constraints refreshed and re-imposed per iteration, reactions for the set.
    """
    @staticmethod
    def ComputeNodalWeights(model_part: ModelPart) -> None:
        """
        NODAL_PAUX := number of SLAVE conditions of "Contact" holding the node.
        """
    def GetInnerLoopIterations(self) -> int:
        ...
    def __init__(self, model_part: ModelPart, scheme: ResidualBasedIncrementalUpdateStaticScheme, convergence_criterion: ConvergenceCriteria, builder_and_solver: BuilderAndSolver, max_iteration: typing.SupportsInt | typing.SupportsIndex = 30, compute_reactions: bool = True, reform_step_dofs: bool = True, move_mesh_flag: bool = True, inner_loop_iterations: typing.SupportsInt | typing.SupportsIndex = 5, update_each_nl_iteration: bool = False, enforce_ntn: bool = False) -> None:
        ...
def AndCriteria(first: ConvergenceCriteria, second: ConvergenceCriteria) -> CompositeCriteria:
    """
    Converged when both criteria are.
    """
def BulkEntities(model_part: ModelPart, elements: bool) -> tuple[numpy.typing.NDArray[numpy.int64], numpy.typing.NDArray[numpy.int64], list[str], numpy.typing.NDArray[numpy.int64], numpy.typing.NDArray[numpy.int64]]:
    """
    (ids, geometry codes, geometry names, node ids, offsets) of the elements (or conditions) of model_part: entity e has geometry names[codes[e]] and the nodes node_ids[offsets[e]:offsets[e + 1]].
    """
def BulkEntityFlags(model_part: ModelPart, elements: bool, flag: Flags) -> numpy.typing.NDArray[numpy.float64]:
    """
    1.0 where the entity is flag, else 0.0.
    """
def BulkEntityValues(model_part: ModelPart, elements: bool, variable: VariableData) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.int64]]:
    """
    (values, sizes) of the non-historical variable on the elements (or conditions) of model_part.
    """
def BulkIntegrationPointValues(model_part: ModelPart, elements: bool, variable: VariableData, process_info: ProcessInfo) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.int64], numpy.typing.NDArray[numpy.int64]]:
    """
    (values, sizes, points): per element (or condition) of model_part the values of variable at its integration points one after the other (padded with zeros to the widest row), the row's length and the number of points.
    """
def BulkNodalCoordinates(model_part: ModelPart, ids: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], initial: bool) -> numpy.typing.NDArray[numpy.float64]:
    """
    (n, 3) initial or current coordinates.
    """
def BulkNodalFlags(model_part: ModelPart, ids: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], flag: Flags) -> numpy.typing.NDArray[numpy.float64]:
    """
    1.0 where the node is flag, else 0.0.
    """
def BulkNodalValues(model_part: ModelPart, ids: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], variable: VariableData, historical: bool) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.int64]]:
    """
    (values, sizes) of variable on the nodes ids of model_part (historical: buffer step 0, else the non-historical value): rows padded with zeros to the widest, and each row's length.
    """
def BulkNodeIds(model_part: ModelPart) -> numpy.typing.NDArray[numpy.int64]:
    """
    Ids of the nodes of model_part in their order, as an int64 array.
    """
def CheckKrylovSettings(krylov_type: str = '', preconditioner_type: str = '', smoother_type: str = '', coarsening_type: str = '') -> None:
    """
    Raises InputError for a krylov_type, preconditioner_type, smoother_type or coarsening_type the PETSc solver does not take (without loading PETSc).
    """
def CreateLinearSolver(solver_type: str = '', tolerance: typing.SupportsFloat | typing.SupportsIndex = 1e-06, max_iteration: typing.SupportsInt | typing.SupportsIndex = 1000, ordering: str = 'auto', krylov_type: str = '', preconditioner_type: str = '', smoother_type: str = '', coarsening_type: str = '', gmres_krylov_space_dimension: typing.SupportsInt | typing.SupportsIndex = 100, verbosity: typing.SupportsInt | typing.SupportsIndex = 0, max_levels: typing.SupportsInt | typing.SupportsIndex = -1, coarse_enough: typing.SupportsInt | typing.SupportsIndex = 1000, pre_sweeps: typing.SupportsInt | typing.SupportsIndex = 1, post_sweeps: typing.SupportsInt | typing.SupportsIndex = 1, reform_preconditioner_at_each_step: bool = True) -> LinearSolver:
    """
    Linear solver for a Kratos or contact_app solver_type name ('' = skyline_lu_factorization: UMFPACK or MUMPS by size); ordering (UMFPACK, MUMPS): 'auto', 'amd' or 'metis'; the other keywords are the amgcl keys of the PETSc Krylov solver (solver_type 'amgcl', 'gmres', 'petsc').
    """
def InspectCheckpoint(data: bytes, source: str) -> dict:
    """
    Header, hash and first section of checkpoint bytes: version, sizes, model part name, TIME, STEP.
    """
def LoadCheckpoint(model_part: ModelPart, data: bytes, source: str) -> None:
    """
    Rebuilds a checkpoint into model_part (an empty root of the saved name); InputError naming source if not intact or not matching, with model_part untouched.
    """
def MortarTypes() -> list[MortarType]:
    """
    Every solver mortar_type, decoded from the condition table.
    """
def MpiRankAndSize() -> tuple[int, int]:
    """
    (rank, ranks) of PETSC_COMM_WORLD (initialises PETSc and MPI; ConfigurationError without PETSc).
    """
def OrCriteria(first: ConvergenceCriteria, second: ConvergenceCriteria) -> CompositeCriteria:
    """
    Converged when either criterion is.
    """
def PetscUnavailableReason() -> str:
    """
    '' when the PETSc solver is available, else why not and which package provides it.
    """
def ResidualBasedLinearStrategy(model_part: ModelPart, scheme: ResidualBasedIncrementalUpdateStaticScheme, builder_and_solver: BuilderAndSolver, compute_reactions: bool = True, reform_step_dofs: bool = False, move_mesh_flag: bool = True) -> SolvingStrategy:
    """
    One build, solve and update per step.
    """
def ResidualBasedNewmarkDisplacementScheme() -> ResidualBasedBossakDisplacementScheme:
    """
    Newmark average-acceleration scheme (Bossak with damp_factor_m = 0).
    """
def ResolveLinearSolverName(solver_type: str) -> str:
    """
    The solver a solver_type name maps to.
    """
def SaveCheckpoint(model_part: ModelPart) -> bytes:
    """
    Checkpoint bytes (header + payload) of the root of model_part.
    """
def create_constitutive_law(name: str) -> ConstitutiveLaw:
    """
    A new law of a registered name; InputError (with a suggestion) for an unknown name.
    """
def create_geometry(name: str, nodes: collections.abc.Sequence[Node]) -> Geometry:
    """
    A geometry of a registered type ("Triangle2D3", ...) on nodes.
    """
def get_flag(name: str) -> Flags:
    """
    The flag called name; KeyError (with a suggestion) for an unknown name.
    """
def get_variable(name: str) -> typing.Any:
    """
    The variable called name; KeyError (with a suggestion) for an unknown name.
    """
def registered_conditions() -> list[str]:
    """
    Sorted condition names.
    """
def registered_constitutive_laws() -> list[str]:
    """
    Sorted constitutive law names.
    """
def registered_constraints() -> list[str]:
    """
    Sorted master-slave constraint names.
    """
def registered_elements() -> list[str]:
    """
    Sorted element names.
    """
def registered_flags() -> list:
    """
    Names of every named flag, in bit order.
    """
def registered_geometries() -> list[str]:
    """
    Sorted geometry type names ("Triangle2D3", ...).
    """
def registered_linear_solvers() -> list[str]:
    """
    Every accepted linear solver_type, sorted.
    """
def registered_variables() -> list[str]:
    """
    Sorted names of every registered variable.
    """
ACCELERATION: Array1DVariable3
ACCELERATION_X: DoubleVariable
ACCELERATION_Y: DoubleVariable
ACCELERATION_Z: DoubleVariable
ACTIVE: Flags
ACTIVE_CHECK_FACTOR: DoubleVariable
ACTIVE_SET_COMPUTED: BoolVariable
ACTIVE_SET_CONVERGED: BoolVariable
ADAPT_PENALTY: BoolVariable
ALMANSI_STRAIN_TENSOR: MatrixVariable
ALMANSI_STRAIN_VECTOR: VectorVariable
ANGULAR_ACCELERATION: Array1DVariable3
ANGULAR_ACCELERATION_X: DoubleVariable
ANGULAR_ACCELERATION_Y: DoubleVariable
ANGULAR_ACCELERATION_Z: DoubleVariable
ANGULAR_VELOCITY: Array1DVariable3
ANGULAR_VELOCITY_X: DoubleVariable
ANGULAR_VELOCITY_Y: DoubleVariable
ANGULAR_VELOCITY_Z: DoubleVariable
AREA_WEIGHTED_PAIR_GAP: DoubleVariable
AREA_WEIGHTED_PAIR_SLIP: Array1DVariable3
AREA_WEIGHTED_PAIR_SLIP_X: DoubleVariable
AREA_WEIGHTED_PAIR_SLIP_Y: DoubleVariable
AREA_WEIGHTED_PAIR_SLIP_Z: DoubleVariable
AUGMENTED_NORMAL_CONTACT_PRESSURE: DoubleVariable
AUGMENTED_TANGENT_CONTACT_PRESSURE: Array1DVariable3
AUGMENTED_TANGENT_CONTACT_PRESSURE_X: DoubleVariable
AUGMENTED_TANGENT_CONTACT_PRESSURE_Y: DoubleVariable
AUGMENTED_TANGENT_CONTACT_PRESSURE_Z: DoubleVariable
AUXILIAR_COORDINATES: Array1DVariable3
AUXILIAR_COORDINATES_X: DoubleVariable
AUXILIAR_COORDINATES_Y: DoubleVariable
AUXILIAR_COORDINATES_Z: DoubleVariable
BLOCKED: Flags
BODY_FORCE: Array1DVariable3
BODY_FORCE_X: DoubleVariable
BODY_FORCE_Y: DoubleVariable
BODY_FORCE_Z: DoubleVariable
BOSSAK_ALPHA: DoubleVariable
BOUNDARY: Flags
BUILD_SCALE_FACTOR: DoubleVariable
CAUCHY_STRESS_TENSOR: MatrixVariable
CAUCHY_STRESS_VECTOR: VectorVariable
CHECKPOINT_FORMAT_VERSION: int = 3
COMPUTE_LUMPED_MASS_MATRIX: BoolVariable
CONSIDER_NORMAL_VARIATION: IntegerVariable
CONSIDER_TESSELLATION: BoolVariable
CONSTITUTIVE_LAW: ConstitutiveLawVariable
CONSTITUTIVE_MATRIX: MatrixVariable
CONSTRAINT_POINTER: VariableData
CONTACT: Flags
CONTACT_FORCE: Array1DVariable3
CONTACT_FORCE_X: DoubleVariable
CONTACT_FORCE_Y: DoubleVariable
CONTACT_FORCE_Z: DoubleVariable
CONTACT_PRESSURE: DoubleVariable
CONVERGENCE_RATIO: DoubleVariable
DEFORMATION_GRADIENT: MatrixVariable
DELTA_COORDINATES: Array1DVariable3
DELTA_COORDINATES_X: DoubleVariable
DELTA_COORDINATES_Y: DoubleVariable
DELTA_COORDINATES_Z: DoubleVariable
DELTA_TIME: DoubleVariable
DENSITY: DoubleVariable
DISPLACEMENT: Array1DVariable3
DISPLACEMENT_X: DoubleVariable
DISPLACEMENT_Y: DoubleVariable
DISPLACEMENT_Z: DoubleVariable
DISTANCE: DoubleVariable
DISTANCE_THRESHOLD: DoubleVariable
DOMAIN_SIZE: IntegerVariable
DYNAMIC_FACTOR: DoubleVariable
ERROR_INTEGRATION_POINT: DoubleVariable
ERROR_RATIO: DoubleVariable
FLUID: Flags
FORCE: Array1DVariable3
FORCE_RESIDUAL: Array1DVariable3
FORCE_RESIDUAL_X: DoubleVariable
FORCE_RESIDUAL_Y: DoubleVariable
FORCE_RESIDUAL_Z: DoubleVariable
FORCE_X: DoubleVariable
FORCE_Y: DoubleVariable
FORCE_Z: DoubleVariable
FREE_SURFACE: Flags
FRICTIONAL_LAW: VariableData
FRICTION_COEFFICIENT: DoubleVariable
GREEN_LAGRANGE_STRAIN_TENSOR: MatrixVariable
GREEN_LAGRANGE_STRAIN_VECTOR: VectorVariable
IDENTIFIER: StringVariable
INDEX_MAP: VariableData
INDEX_SET: VariableData
INITIAL_PENALTY: DoubleVariable
INITIAL_STRAIN_VECTOR: VectorVariable
INLET: Flags
INNER_LOOP_ITERATION: IntegerVariable
INSIDE: Flags
INTEGRATION_ORDER: IntegerVariable
INTEGRATION_ORDER_CONTACT: IntegerVariable
INTERACTION: Flags
INTERFACE: Flags
ISOLATED: Flags
IS_RESTARTED: BoolVariable
LAGRANGE_MULTIPLIER_CONTACT_PRESSURE: DoubleVariable
LINE_LOAD: Array1DVariable3
LINE_LOAD_X: DoubleVariable
LINE_LOAD_Y: DoubleVariable
LINE_LOAD_Z: DoubleVariable
MARKER: Flags
MASS_FACTOR: DoubleVariable
MASTER: Flags
MASTER_SLAVE_CONSTRAINT: VariableData
MAX_GAP_FACTOR: DoubleVariable
MAX_GAP_THRESHOLD: DoubleVariable
MESH_DISPLACEMENT: Array1DVariable3
MESH_DISPLACEMENT_X: DoubleVariable
MESH_DISPLACEMENT_Y: DoubleVariable
MESH_DISPLACEMENT_Z: DoubleVariable
MODIFIED: Flags
MPI_BOUNDARY: Flags
NEGATIVE_FACE_PRESSURE: DoubleVariable
NEWMARK_BETA: DoubleVariable
NEWMARK_GAMMA: DoubleVariable
NEW_ENTITY: Flags
NL_ITERATION_NUMBER: IntegerVariable
NODAL_AREA: DoubleVariable
NODAL_H: DoubleVariable
NODAL_MASS: DoubleVariable
NODAL_MAUX: DoubleVariable
NODAL_PAUX: DoubleVariable
NODAL_VAUX: Array1DVariable3
NODAL_VAUX_X: DoubleVariable
NODAL_VAUX_Y: DoubleVariable
NODAL_VAUX_Z: DoubleVariable
NORMAL: Array1DVariable3
NORMAL_CONTACT_STRESS: DoubleVariable
NORMAL_GAP: DoubleVariable
NORMAL_X: DoubleVariable
NORMAL_Y: DoubleVariable
NORMAL_Z: DoubleVariable
OLD_ENTITY: Flags
OPERATOR_THRESHOLD: DoubleVariable
OUTLET: Flags
PAIRED_NORMAL: Array1DVariable3
PAIRED_NORMAL_X: DoubleVariable
PAIRED_NORMAL_Y: DoubleVariable
PAIRED_NORMAL_Z: DoubleVariable
PERIODIC: Flags
PK2_STRESS_TENSOR: MatrixVariable
PK2_STRESS_VECTOR: VectorVariable
POINT_LOAD: Array1DVariable3
POINT_LOAD_X: DoubleVariable
POINT_LOAD_Y: DoubleVariable
POINT_LOAD_Z: DoubleVariable
POINT_MOMENT: Array1DVariable3
POINT_MOMENT_X: DoubleVariable
POINT_MOMENT_Y: DoubleVariable
POINT_MOMENT_Z: DoubleVariable
POISSON_RATIO: DoubleVariable
POSITIVE_FACE_PRESSURE: DoubleVariable
PRESSURE: DoubleVariable
RAYLEIGH_ALPHA: DoubleVariable
RAYLEIGH_BETA: DoubleVariable
REACTION: Array1DVariable3
REACTION_CHECK_STIFFNESS_FACTOR: DoubleVariable
REACTION_MOMENT: Array1DVariable3
REACTION_MOMENT_X: DoubleVariable
REACTION_MOMENT_Y: DoubleVariable
REACTION_MOMENT_Z: DoubleVariable
REACTION_X: DoubleVariable
REACTION_Y: DoubleVariable
REACTION_Z: DoubleVariable
RESET_EQUATION_IDS: BoolVariable
RESIDUAL_NORM: DoubleVariable
RESTART_PROCESS_STATES: StringVariable
RIGID: Flags
ROTATION: Array1DVariable3
ROTATION_X: DoubleVariable
ROTATION_Y: DoubleVariable
ROTATION_Z: DoubleVariable
SCALAR_LAGRANGE_MULTIPLIER: DoubleVariable
SCALE_FACTOR: DoubleVariable
SELECTED: Flags
SLAVE: Flags
SLIP: Flags
SLIP_AUGMENTATION_COEFFICIENT: DoubleVariable
SLIP_SET_CONVERGED: BoolVariable
SLIP_THRESHOLD: DoubleVariable
SLIP_TRIAL_FACTOR: DoubleVariable
SOLID: Flags
SQUARED_PAIR_AREA: DoubleVariable
STEP: IntegerVariable
STRAIN_ENERGY: DoubleVariable
STRUCTURE: Flags
SURFACE_LOAD: Array1DVariable3
SURFACE_LOAD_X: DoubleVariable
SURFACE_LOAD_Y: DoubleVariable
SURFACE_LOAD_Z: DoubleVariable
TABLE_UTILITY: VariableData
TANGENTIAL_CONTACT_STRESS: DoubleVariable
TANGENT_ETA: Array1DVariable3
TANGENT_ETA_X: DoubleVariable
TANGENT_ETA_Y: DoubleVariable
TANGENT_ETA_Z: DoubleVariable
TANGENT_FACTOR: DoubleVariable
TANGENT_SLIP: Array1DVariable3
TANGENT_SLIP_X: DoubleVariable
TANGENT_SLIP_Y: DoubleVariable
TANGENT_SLIP_Z: DoubleVariable
TANGENT_XI: Array1DVariable3
TANGENT_XI_X: DoubleVariable
TANGENT_XI_Y: DoubleVariable
TANGENT_XI_Z: DoubleVariable
TEMPERATURE: DoubleVariable
THERMAL: Flags
THICKNESS: DoubleVariable
TIME: DoubleVariable
TO_ERASE: Flags
TO_REFINE: Flags
TO_SPLIT: Flags
TRESCA_FRICTION_THRESHOLD: DoubleVariable
TYING_VARIABLE: StringVariable
VECTOR_LAGRANGE_MULTIPLIER: Array1DVariable3
VECTOR_LAGRANGE_MULTIPLIER_X: DoubleVariable
VECTOR_LAGRANGE_MULTIPLIER_Y: DoubleVariable
VECTOR_LAGRANGE_MULTIPLIER_Z: DoubleVariable
VELOCITY: Array1DVariable3
VELOCITY_X: DoubleVariable
VELOCITY_Y: DoubleVariable
VELOCITY_Z: DoubleVariable
VISITED: Flags
VOLUME_ACCELERATION: Array1DVariable3
VOLUME_ACCELERATION_X: DoubleVariable
VOLUME_ACCELERATION_Y: DoubleVariable
VOLUME_ACCELERATION_Z: DoubleVariable
VON_MISES_STRESS: DoubleVariable
WEIGHTED_GAP: DoubleVariable
WEIGHTED_SCALAR_RESIDUAL: DoubleVariable
WEIGHTED_SLIP: Array1DVariable3
WEIGHTED_SLIP_X: DoubleVariable
WEIGHTED_SLIP_Y: DoubleVariable
WEIGHTED_SLIP_Z: DoubleVariable
WEIGHTED_VECTOR_RESIDUAL: Array1DVariable3
WEIGHTED_VECTOR_RESIDUAL_X: DoubleVariable
WEIGHTED_VECTOR_RESIDUAL_Y: DoubleVariable
WEIGHTED_VECTOR_RESIDUAL_Z: DoubleVariable
YOUNG_MODULUS: DoubleVariable
ZERO_TOLERANCE_FACTOR: DoubleVariable
Scheme = ResidualBasedIncrementalUpdateStaticScheme
