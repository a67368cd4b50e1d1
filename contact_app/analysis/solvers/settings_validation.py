"""Conversion and validation of ``solver_settings`` (Kratos ``MechanicalSolver.ValidateSettings``).

The key tables of the sub-blocks (linear solver, time stepping, line search, model import), the
conversion of the deprecated keys old files use (:func:`convert_deprecated_settings`, a warning
each), and one check per part of ``solver_settings``: the top-level keys, the strategy, the builder
and solver, the linear solver, the time stepping, the model import (which resolves the mesh or
restart file, :class:`ModelInput`), the materials import and the auxiliary lists.
:meth:`MechanicalSolver.ValidateSettings` calls them in that order; the contact solvers extend it.
Each function raises InputError (with where and a fix) or ConfigurationError (a valid Kratos
option contact_app does not implement).
"""

from __future__ import annotations

import logging
from dataclasses import dataclass, field
from typing import Any

import contact_app as ca

from ...legacy_keys import convert_legacy_keys
from ...parameters import Parameters, suggest
from ..materials import MaterialsReader
from ..paths import PathResolver
from ..validation import choice, error, not_supported, positive

# The logger of the solver the checks belong to: their warnings read as the solver's.
logger = logging.getLogger("contact_app.analysis")

#: Every key a ``linear_solver_settings`` block may hold (Kratos linear solver factories). Only
#: ``solver_type``, ``tolerance``, ``max_iteration``, ``ordering`` (contact_app's own: UMFPACK's
#: fill-reducing ordering, "auto", "amd" or "metis") and ``static_condensation`` (contact_app's
#: own: "auto", true or false; None here because it takes a string or a bool, checked by
#: :func:`static_condensation_mode`) change what contact_app does; the others tune Kratos'
#: iterative solvers and are accepted and ignored.
LINEAR_SOLVER_KEYS: dict[str, Any] = {
    "solver_type": "",
    "tolerance": 1.0e-6,
    "max_iteration": 1000,
    "ordering": "auto",
    "static_condensation": None,
    "scaling": False,
    "verbosity": 0,
    "echo_level": 0,
    "preconditioner_type": "",
    "krylov_type": "",
    "smoother_type": "",
    "coarsening_type": "",
    "gmres_krylov_space_dimension": 100,
    "block_size": 1,
    "use_block_matrices_if_possible": True,
    "coarse_enough": 1000,
    "max_levels": -1,
    "pre_sweeps": 1,
    "post_sweeps": 1,
    "use_gpgpu": False,
    "provide_coordinates": False,
    "reform_preconditioner_at_each_step": True,
    "symmetric_scaling": True,
}

#: The ``linear_solver_settings`` keys the PETSc Krylov solver (solver_type "amgcl", "gmres")
#: honours beyond tolerance and max_iteration (docs/running.md, "Iterative solver (PETSc)").
KRYLOV_KEYS = (
    "krylov_type",
    "preconditioner_type",
    "smoother_type",
    "coarsening_type",
    "gmres_krylov_space_dimension",
    "verbosity",
    "max_levels",
    "coarse_enough",
    "pre_sweeps",
    "post_sweeps",
    "reform_preconditioner_at_each_step",
)
#: Solvers of the iterative route: no static condensation under "auto", every ALM family condensed.
ITERATIVE_SOLVERS = ("petsc",)

TIME_STEPPING_KEYS: dict[str, Any] = {
    "time_step": 1.0,
    "time_step_table": [],
    "time_step_intervals": {},
}

LINE_SEARCH_KEYS: dict[str, Any] = {
    "max_line_search_iterations": 5,
    "first_alpha_value": 0.5,
    "second_alpha_value": 1.0,
    "min_alpha": 0.1,
    "max_alpha": 2.0,
    "line_search_tolerance": 0.5,
}

MODEL_IMPORT_KEYS: dict[str, Any] = {
    "input_type": "mdpa",
    "input_filename": "",
    "reorder": False,
    "skip_timer": True,
    "ignore_variables_not_in_solution_step_data": False,
    "mesh_mapping": {},
    # input_type "rest" (Kratos RestartUtility):
    # <input_filename>__restart_files/<input_filename>_<label>.rest
    "restart_load_file_label": "",
    "load_restart_files_from_folder": True,
    "serializer_trace": "no_trace",
}
#: Extensions read through meshio when input_type is left at "mdpa" (detection by extension).
MESHIO_EXTENSIONS = (
    ".msh",
    ".vtu",
    ".vtk",
    ".inp",
    ".med",
    ".xdmf",
    ".xmf",
    ".mesh",
    ".obj",
    ".ply",
)

_FEATURE_FLAGS = {
    "volumetric_strain_dofs": "mixed displacement/volumetric-strain elements",
    "strain_dofs": "mixed displacement/strain elements",
    "pressure_dofs": "mixed displacement/pressure elements",
    "displacement_control": "displacement control",
    "rotation_dofs": "rotation DoFs (shells, beams)",
    "use_orthogonal_subscales": "orthogonal subscales",
    "use_old_stiffness_in_first_iteration": "use_old_stiffness_in_first_iteration",
}

#: ``on_non_converged_step``: "stop" (default) ends the run at a step that did not converge (after
#: step cutting, when it is on); "continue" goes on from that state, as Kratos does by default.
NON_CONVERGED_STEP_POLICIES = ("stop", "continue")


@dataclass(frozen=True)
class ModelInput:
    """The file ``model_import_settings`` names, resolved ("" for the kinds it is not).

    Attributes:
        mdpa_path: the .mdpa file (``input_type`` "mdpa").
        meshio_path: the mesh read through meshio (``input_type`` "meshio", or by extension).
        meshio_mapping: the ``mesh_mapping`` of a meshio mesh.
        meshio_where: where ``mesh_mapping`` is, for the messages of the meshio import.
        restart_path: the restart file (``input_type`` "rest").

    """

    mdpa_path: str = ""
    meshio_path: str = ""
    meshio_mapping: dict[str, Any] = field(default_factory=dict)
    meshio_where: str = ""
    restart_path: str = ""


def is_iterative(linear: Parameters) -> bool:
    """Whether ``linear_solver_settings.solver_type`` maps to the PETSc Krylov solver."""
    name = linear["solver_type"].GetString() if linear.Has("solver_type") else ""
    try:
        return bool(ca.ResolveLinearSolverName(name) in ITERATIVE_SOLVERS)
    except ca.InputError:
        return False


def static_condensation_mode(linear: Parameters) -> str:
    """``linear_solver_settings.static_condensation`` as the solver's mode: "auto", "on" or "off".

    Raises:
        InputError: neither "auto" nor a bool.

    """
    if not linear.Has("static_condensation"):
        return "auto"
    value = linear["static_condensation"]
    if value.IsBool():
        return "on" if value.GetBool() else "off"
    if value.IsString() and value.GetString() == "auto":
        return "auto"
    raise error(
        linear,
        "static_condensation",
        f"static_condensation is {value.WriteJsonString()}",
        '"auto", true or false',
        'remove the key ("auto": condense when the bodies are linear and the system is large), '
        "or give true / false",
    )


def convert_deprecated_settings(settings: Parameters) -> None:
    """Translate the keys of old files in ``solver_settings`` (Kratos does the same, warning each).

    Raises:
        InputError: both the deprecated block_builder and builder_and_solver_settings.type given,
            or a legacy key beside its current one.

    """
    convert_legacy_keys(settings, "solver_settings")  # renamed and removed keys (one table)
    if settings.Has("model_import_settings"):
        convert_legacy_keys(settings["model_import_settings"], "model_import_settings")
    if settings.Has("block_builder"):
        use_block = settings["block_builder"].GetBool()
        if settings.Has("builder_and_solver_settings") and settings[
            "builder_and_solver_settings"
        ].Has("type"):
            raise error(
                settings,
                "block_builder",
                "both the deprecated block_builder and builder_and_solver_settings.type given",
                "only builder_and_solver_settings.type",
                'remove "block_builder"',
            )
        if not settings.Has("builder_and_solver_settings"):
            settings.AddValue("builder_and_solver_settings", {})
        settings["builder_and_solver_settings"].AddValue("use_block_builder", use_block)
        logger.warning(
            '%s is deprecated; converted to builder_and_solver_settings.type = "%s"',
            settings.Where("block_builder"),
            "block" if use_block else "elimination",
        )
        settings.RemoveValue("block_builder")
    if settings.Has("builder_and_solver_settings"):
        builder = settings["builder_and_solver_settings"]
        if builder.IsSubParameter() and not builder.Has("type"):
            use_block = (
                builder["use_block_builder"].GetBool() if builder.Has("use_block_builder") else True
            )
            lagrange = (
                builder["use_lagrange_BS"].GetBool() if builder.Has("use_lagrange_BS") else False
            )
            kind = ("block_lagrange" if lagrange else "block") if use_block else "elimination"
            for key in ("use_block_builder", "use_lagrange_BS"):
                builder.RemoveValue(key)
            builder.AddValue("type", kind)
    if settings.Has("line_search"):
        use_line_search = settings["line_search"].GetBool()
        if use_line_search:
            if not settings.Has("solving_strategy_settings"):
                settings.AddValue("solving_strategy_settings", {"type": "line_search"})
            else:
                settings["solving_strategy_settings"].AddValue("type", "line_search")
        logger.warning(
            "%s is deprecated; %s",
            settings.Where("line_search"),
            'converted to solving_strategy_settings.type = "line_search"'
            if use_line_search
            else "false is the default; removed",
        )
        settings.RemoveValue("line_search")


def validate_top_level_keys(settings: Parameters) -> None:
    """Check the plain keys of ``solver_settings``: names, enumerations, unsupported features.

    Raises:
        InputError: an empty model_part_name, a domain_size other than 2 or 3, a bad choice.
        ConfigurationError: a feature flag (mixed elements, rotation DoFs, ...) set to true.

    """
    if not settings["model_part_name"].GetString():
        raise error(
            settings, "model_part_name", "model_part_name is empty", 'a name like "Structure"'
        )
    domain_size = settings["domain_size"].GetInt()
    if domain_size not in (2, 3):
        raise error(settings, "domain_size", f"domain_size is {domain_size}", "2 or 3")
    # Numbers (echo_level, buffer_size, max_iteration, tolerances) were range-checked by
    # ValidateAndAssignDefaults (contact_app/setting_ranges.py).
    for key, feature in _FEATURE_FLAGS.items():
        if settings[key].GetBool():
            raise not_supported(settings, key, feature, f'set "{key}": false or remove it')
    choice(settings, "analysis_type", ("linear", "non_linear"))
    choice(settings, "on_non_converged_step", NON_CONVERGED_STEP_POLICIES)


def validate_strategy_settings(strategy: Parameters) -> None:
    """Check ``solving_strategy_settings`` and assign its defaults (line search ones included).

    Raises:
        InputError: an unknown type, or advanced settings for Newton-Raphson.
        ConfigurationError: the arc-length strategy.

    """
    strategy.ValidateAndAssignDefaults({"type": "newton_raphson", "advanced_settings": {}})
    kind = choice(
        strategy, "type", ("newton_raphson", "line_search", "arc_length"), "solving strategy"
    )
    if kind == "arc_length":
        raise not_supported(
            strategy, "type", "the arc-length strategy", 'use "newton_raphson" or "line_search"'
        )
    advanced = strategy["advanced_settings"]
    if kind == "line_search":
        advanced.ValidateAndAssignDefaults(LINE_SEARCH_KEYS)
    elif advanced.size():
        key = advanced.keys()[0]
        raise error(
            advanced,
            key,
            f'unknown key "{key}": the Newton-Raphson strategy has no advanced settings',
            "an empty object",
            'remove it (line search settings need "type": "line_search")',
        )


def validate_builder_settings(builder: Parameters) -> None:
    """Check ``builder_and_solver_settings`` and assign its defaults.

    Raises:
        InputError: an unknown type.
        ConfigurationError: the block builder with Lagrange constraints, or advanced settings.

    """
    builder.ValidateAndAssignDefaults({"type": "block", "advanced_settings": {}})
    kind = choice(builder, "type", ("block", "block_lagrange", "elimination"), "builder and solver")
    if kind == "block_lagrange":
        raise not_supported(
            builder, "type", "the block builder with Lagrange constraints", 'use "block"'
        )
    advanced = builder["advanced_settings"]
    if advanced.size():
        raise not_supported(
            advanced, advanced.keys()[0], "builder and solver advanced settings", "remove them"
        )


def validate_linear_solver_settings(linear: Parameters) -> None:
    """Check ``linear_solver_settings`` on a copy: the block keeps only the keys it was given.

    Raises:
        InputError: an unknown key or solver_type, a bad tolerance, Krylov settings,
            static_condensation or ordering; each located at its key.

    """
    linear.Clone().ValidateAndAssignDefaults(LINEAR_SOLVER_KEYS)
    if linear.Has("solver_type"):
        name = linear["solver_type"].GetString()
        try:
            ca.ResolveLinearSolverName(name)
        except ca.InputError as failure:
            first, _, rest = str(failure).partition("\n")
            raise ca.InputError(
                f"{first}\n  where:    {linear.Where('solver_type')}\n{rest}"
            ) from None
    if linear.Has("tolerance"):
        positive(linear, "tolerance")
    strings = ("krylov_type", "preconditioner_type", "smoother_type", "coarsening_type")
    if is_iterative(linear) and any(linear.Has(key) for key in strings):
        given = {key: linear[key].GetString() for key in strings if linear.Has(key)}
        try:
            ca.CheckKrylovSettings(**given)
        except ca.InputError as failure:
            first, _, rest = str(failure).partition("\n")
            key = next((k for k in given if f".{k} " in first), "solver_type")
            where = linear.Where(key)
            raise ca.InputError(f"{first}\n  where:    {where}\n{rest}") from None
    static_condensation_mode(linear)
    if linear.Has("ordering"):
        solver_type = linear["solver_type"].GetString() if linear.Has("solver_type") else ""
        try:
            ca.CreateLinearSolver(solver_type, ordering=linear["ordering"].GetString())
        except ca.InputError as failure:
            first, _, rest = str(failure).partition("\n")
            raise ca.InputError(
                f"{first}\n  where:    {linear.Where('ordering')}\n{rest}"
            ) from None


def validate_time_stepping(stepping: Parameters) -> None:
    """Check ``time_stepping``: exactly one of time_step, time_step_table, time_step_intervals.

    Raises:
        InputError: none or several given, a table that is not increasing rows of [time, dt > 0],
            or empty or malformed intervals.

    """
    stepping.Clone().ValidateAndAssignDefaults(TIME_STEPPING_KEYS)
    given = [key for key in TIME_STEPPING_KEYS if stepping.Has(key)]
    if len(given) != 1:
        raise error(
            stepping,
            None,
            "time_stepping must give exactly one of time_step, time_step_table, "
            f"time_step_intervals (found {', '.join(given) or 'none'})",
            '{"time_step": 0.1}',
            "give one constant time_step, or a table [[time, dt], ...]",
        )
    if stepping.Has("time_step"):
        pass  # its range is checked with the defaults (contact_app/setting_ranges.py)
    elif stepping.Has("time_step_table"):
        rows = stepping["time_step_table"].GetMatrix()
        if not rows or any(len(row) != 2 for row in rows):
            raise error(
                stepping,
                "time_step_table",
                "time_step_table is not rows of [time, dt]",
                "[[0.0, 0.1], [1.0, 0.2]]",
            )
        if any(row[1] <= 0.0 for row in rows):
            raise error(
                stepping,
                "time_step_table",
                "time_step_table has a dt ≤ 0",
                "positive time steps",
            )
        if any(b[0] <= a[0] for a, b in zip(rows, rows[1:], strict=False)):
            raise error(
                stepping,
                "time_step_table",
                "the times of time_step_table do not increase",
                "increasing times",
            )
    else:
        intervals = stepping["time_step_intervals"]
        if not intervals.size():
            raise error(
                stepping,
                "time_step_intervals",
                "time_step_intervals is empty",
                '{"0": {"interval": [0.0, "End"], "time_step": 0.1}}',
            )
        for interval in intervals.values():
            interval.ValidateAndAssignDefaults({"interval": [0.0, "End"], "time_step": 1.0})
            interval_bounds(interval)
        logger.warning(
            "%s is deprecated; use time_step or time_step_table",
            stepping.Where("time_step_intervals"),
        )


def interval_bounds(interval: Parameters) -> tuple[float, float]:
    """(begin, end) of one ``time_step_intervals`` entry; "End" is 1e30.

    Raises:
        InputError: ``interval`` is not [begin, end].

    """
    bounds = interval["interval"]
    values = bounds.GetValue()
    if not (isinstance(values, list) and len(values) == 2):
        raise error(
            interval, "interval", "interval is not [begin, end]", '[0.0, 1.0] or [0.0, "End"]'
        )
    begin = bounds[0].GetDouble()
    end = 1.0e30 if values[1] == "End" else bounds[1].GetDouble()
    return begin, end


def validate_model_import(
    settings: Parameters, model_part_name: str, paths: PathResolver
) -> ModelInput:
    """Check ``model_import_settings`` and resolve the file it names (before anything is read).

    Args:
        settings: the ``model_import_settings`` block; its defaults are assigned.
        model_part_name: ``solver_settings.model_part_name``, which a restart file must hold.
        paths: how relative paths resolve.

    Raises:
        InputError: a bad input_type, a missing or unreadable file, a mesh_mapping that is not
            an object or is given for an .mdpa file, a restart file of another model part.

    """
    settings.ValidateAndAssignDefaults(MODEL_IMPORT_KEYS)
    kind = choice(
        settings,
        "input_type",
        ("mdpa", "meshio", "use_input_model_part", "rest"),
        "input_type",
    )
    filename = settings["input_filename"].GetString()
    if kind == "rest":
        return ModelInput(
            restart_path=validate_restart_import(settings, filename, model_part_name, paths)
        )
    if kind == "mdpa" and filename.lower().endswith(MESHIO_EXTENSIONS):
        kind = "meshio"
    if kind == "meshio":
        if not filename:
            raise error(
                settings,
                "input_filename",
                'missing required key "input_filename"',
                "the mesh file name with its extension, e.g. hertz_2d.msh",
            )
        meshio_path = paths.input_path(filename, settings.Where("input_filename"), "mesh file")
        if not settings["mesh_mapping"].IsSubParameter():
            raise error(settings, "mesh_mapping", "mesh_mapping is not an object", "{...}")
        return ModelInput(
            meshio_path=meshio_path,
            meshio_mapping=settings["mesh_mapping"].GetValue(),
            meshio_where=settings.Where("mesh_mapping"),
        )
    if settings["mesh_mapping"].size():
        raise error(
            settings,
            "mesh_mapping",
            'mesh_mapping is only read with "input_type": "meshio"',
            "no mesh_mapping for an .mdpa file",
            "remove it, or read the mesh through meshio",
        )
    if kind != "mdpa":
        return ModelInput()  # use_input_model_part: the model part is already there
    if not filename:
        raise error(
            settings,
            "input_filename",
            'missing required key "input_filename"',
            "the mdpa file name without the .mdpa extension",
            '"input_filename": "my_case" for my_case.mdpa',
        )
    if filename.endswith(".mdpa"):
        logger.warning(
            "%s includes the .mdpa extension, which Kratos would add again; used as given",
            settings.Where("input_filename"),
        )
        filename = filename[: -len(".mdpa")]
    return ModelInput(
        mdpa_path=paths.input_path(
            filename + ".mdpa", settings.Where("input_filename"), "mdpa file"
        )
    )


def validate_restart_import(
    settings: Parameters, filename: str, model_part_name: str, paths: PathResolver
) -> str:
    """input_type "rest": the restart file must exist; its header and hash are checked here.

    Returns:
        The path of the restart file.

    Raises:
        InputError: a bad serializer_trace, no input_filename or label, a missing file, or a
            file that holds another model part than ``model_part_name``.

    """
    from ...io.restart_utility import SERIALIZER_TRACES, Inspect, RestartFile

    choice(settings, "serializer_trace", SERIALIZER_TRACES, "serializer_trace")
    label = settings["restart_load_file_label"].GetString()
    for key, value, expected in (
        ("input_filename", filename, "the base name of the restart files, e.g. hertz_2d"),
        ("restart_load_file_label", label, 'the TIME or STEP label of the file, e.g. "0.5"'),
    ):
        if not value:
            raise error(
                settings, key, f'missing required key "{key}" for input_type "rest"', expected
            )
    name = RestartFile(filename, label, settings["load_restart_files_from_folder"].GetBool())
    restart_path = paths.input_path(
        str(name), settings.Where("restart_load_file_label"), "restart file"
    )
    summary = Inspect(restart_path)
    if summary["model_part_name"] != model_part_name:
        raise error(
            settings,
            "restart_load_file_label",
            f'the restart file "{restart_path}" holds the model part '
            f'"{summary["model_part_name"]}", not "{model_part_name}"',
            "a restart file of solver_settings.model_part_name",
            "pick the restart file of this model part",
        )
    return restart_path


def validate_material_import(settings: Parameters, paths: PathResolver) -> MaterialsReader | None:
    """Check ``material_import_settings`` and read the materials file (None when there is none).

    Raises:
        InputError: a missing or invalid materials file.
        ConfigurationError: a custom_reader.

    """
    settings.ValidateAndAssignDefaults({"materials_filename": "", "custom_reader": ""})
    if settings["custom_reader"].GetString():
        raise not_supported(
            settings, "custom_reader", "a custom materials reader", "use materials_filename"
        )
    filename = settings["materials_filename"].GetString()
    if not filename:
        return None
    path = paths.input_path(filename, settings.Where("materials_filename"), "materials file")
    return MaterialsReader(path)


def validate_auxiliary_lists(settings: Parameters) -> None:
    """Check the auxiliary variable, DoF and reaction lists of ``solver_settings``.

    Raises:
        InputError: an unregistered variable, or not one reaction per auxiliary DoF.

    """
    for key in ("auxiliary_variables_list", "auxiliary_dofs_list", "auxiliary_reaction_list"):
        for index, name in enumerate(settings[key].GetStringArray()):
            if name not in ca.registered_variables():
                raise error(
                    settings[key],
                    f"[{index}]",
                    f'unknown variable "{name}"',
                    "a registered variable",
                    suggest(name, ca.registered_variables()),
                )
    dofs = settings["auxiliary_dofs_list"].GetStringArray()
    reactions = settings["auxiliary_reaction_list"].GetStringArray()
    if len(dofs) != len(reactions):
        raise error(
            settings,
            "auxiliary_reaction_list",
            f"{len(dofs)} auxiliary DoFs but {len(reactions)} reactions",
            "one reaction per auxiliary DoF",
        )
