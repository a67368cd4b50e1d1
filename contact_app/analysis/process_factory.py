"""Process descriptors → process objects (Kratos ``process_factory.KratosProcessFactory``).

A descriptor is ``{"python_module": ..., "kratos_module": ..., "process_name": ..., "help": ...,
"Parameters": {...}}``. ``kratos_module`` may omit the ``KratosMultiphysics.`` prefix. The Kratos
modules map to contact_app packages:

* ``KratosMultiphysics`` and ``KratosMultiphysics.StructuralMechanicsApplication`` →
  ``contact_app.processes``;
* ``KratosMultiphysics.ContactStructuralMechanicsApplication`` → ``contact_app.contact``.

Without ``kratos_module`` the module is looked up in ``contact_app.processes`` first, then
imported as a plain module (a user's own process next to the parameters file; Kratos imports it
the same way): that runs the case folder's code, so a case from an untrusted source is run with
``safe`` (``contact-app run --safe``), which refuses every module outside contact_app's own
packages. A module name must be an absolute dotted name (``..evil`` is refused). The module's
``Factory(descriptor, model)`` creates the process. A newer-style
``"name": "Processes.KratosMultiphysics.AssignVectorVariableProcess"`` selects the module of that
class. ``gid_output_process`` blocks are skipped with a warning (GiD output is not available).
"""

from __future__ import annotations

import importlib
import logging
import os
import pkgutil
import re
import sys
from collections.abc import Callable
from types import ModuleType
from typing import Any

import contact_app as ca

from ..json_input import quote
from ..legacy_keys import convert_legacy_keys
from ..parameters import Parameters, suggest
from .paths import PathResolver
from .validation import error

logger = logging.getLogger("contact_app.analysis")

CORE_PACKAGE = "contact_app.processes"
CONTACT_PACKAGE = "contact_app.contact"
PACKAGES = {
    "KratosMultiphysics": CORE_PACKAGE,
    "KratosMultiphysics.StructuralMechanicsApplication": CORE_PACKAGE,
    "KratosMultiphysics.ContactStructuralMechanicsApplication": CONTACT_PACKAGE,
}
DESCRIPTOR_KEYS = (
    "python_module",
    "kratos_module",
    "process_name",
    "help",
    "check",
    "Parameters",
    "name",
)
SKIPPED_MODULES = {
    "gid_output_process": "GiD output is not available in contact_app; use vtk_output_process",
}
#: Keys of process ``Parameters`` that name files to read or write (resolved like the solver's).
INPUT_PATH_KEYS = ("input_file_name",)
OUTPUT_PATH_KEYS = ("output_file_name", "output_path", "folder_name")
_MODULE_NAME = re.compile(r"[A-Za-z_]\w*(\.[A-Za-z_]\w*)*")


def _snake_case(name: str) -> str:
    return re.sub(r"(?<=[a-z0-9])(?=[A-Z])", "_", name).lower()


def _package_modules(package: str) -> list[str]:
    try:
        module = importlib.import_module(package)
    except ModuleNotFoundError:
        return []
    names = (info.name for info in pkgutil.iter_modules(module.__path__))
    return sorted(name for name in names if name.endswith("_process"))


def _import(full_name: str) -> ModuleType | None:
    """Import ``full_name``; None if that module (not one it imports) does not exist."""
    try:
        return importlib.import_module(full_name)
    except ModuleNotFoundError as failure:
        if failure.name is not None and full_name.startswith(failure.name):
            return None
        raise


class KratosProcessFactory:
    """Create processes from descriptor lists.

    Args:
        model: the model the processes act on.
        paths: how relative file names in process settings resolve.
        safe: import only contact_app's own process modules, never one from the case folder,
            the working directory or ``sys.path``.

    """

    def __init__(self, model: ca.Model, paths: PathResolver | None = None, *, safe: bool = False):
        self.model = model
        self.paths = paths or PathResolver()
        self.safe = safe

    # -- resolution --

    def _module_names(self, item: Parameters) -> tuple[str, str | None]:
        """Return (python_module, kratos_module or None) of a descriptor."""
        if item.Has("python_module"):
            python_module = item["python_module"].GetString()
        elif item.Has("name"):
            written = item["name"].GetString()
            parts = written.split(".")
            python_module = _snake_case(parts[-1])
            kratos = ".".join(p for p in parts[:-1] if p != "Processes")
            return python_module, kratos or None
        else:
            raise error(
                item,
                "python_module",
                'missing required key "python_module"',
                'the module of the process, e.g. "assign_vector_variable_process"',
                'add "python_module" (and "kratos_module": "KratosMultiphysics")',
            )
        kratos_module = item["kratos_module"].GetString() if item.Has("kratos_module") else None
        return python_module, kratos_module

    def ResolveModule(self, item: Parameters) -> ModuleType | None:
        """Return the module of a descriptor (None for a skipped one), checking it has ``Factory``.

        Raises:
            InputError: not an object, unknown descriptor key, missing python_module, unknown
                kratos_module or python_module (with the closest names), contact module not
                implemented yet, module without Factory.

        """
        if not item.IsSubParameter():
            raise error(
                item,
                None,
                "a process descriptor is not an object",
                '{"python_module": ..., "Parameters": {...}}',
            )
        for key in item.keys():
            if key not in DESCRIPTOR_KEYS:
                raise error(
                    item,
                    key,
                    f'unknown key "{quote(key)}" in a process descriptor',
                    "one of " + ", ".join(f'"{k}"' for k in DESCRIPTOR_KEYS),
                    suggest(key, list(DESCRIPTOR_KEYS)),
                )
        python_module, kratos_module = self._module_names(item)
        key = "python_module" if item.Has("python_module") else "name"
        if not _MODULE_NAME.fullmatch(python_module):
            raise error(
                item,
                key,
                f'"{quote(python_module)}" is not a module name',
                'an absolute module name such as "assign_vector_variable_process" or '
                '"my_package.my_process" (letters, digits, "_", separated by single dots)',
                "relative names (a leading dot) and paths cannot be imported; write the name",
            )
        if python_module in SKIPPED_MODULES:
            logger.warning("%s skipped: %s", item.Where(), SKIPPED_MODULES[python_module])
            return None
        if kratos_module is None:
            module = _import(f"{CORE_PACKAGE}.{python_module}") or self._ImportUserModule(
                item, key, python_module
            )
            if module is None:
                raise self._UnknownModule(item, key, python_module, CORE_PACKAGE)
            return self._CheckFactory(item, module)
        full = (
            kratos_module
            if kratos_module.startswith("KratosMultiphysics")
            else f"KratosMultiphysics.{kratos_module}"
        )
        package = PACKAGES.get(full)
        if package is None:
            raise error(
                item,
                "kratos_module",
                f'unknown kratos_module "{quote(kratos_module)}"',
                "one of " + ", ".join(f'"{k}"' for k in PACKAGES),
                suggest(full, list(PACKAGES))
                or "processes of other Kratos applications are not available",
            )
        if package == CONTACT_PACKAGE and _import(CONTACT_PACKAGE) is None:
            raise ca.InputError(
                f'the contact package for "{python_module}" ({full}) is not installed\n'
                f"  where:    {item.Where(key)}\n"
                "  fix:      reinstall contact_app (scripts/bootstrap.sh)"
            )
        module = _import(f"{package}.{python_module}")
        if module is None:
            raise self._UnknownModule(item, key, python_module, package)
        return self._CheckFactory(item, module)

    def _ImportUserModule(
        self, item: Parameters, key: str, python_module: str
    ) -> ModuleType | None:
        if self.safe:
            known = _package_modules(CORE_PACKAGE)
            hint = suggest(python_module, known)
            raise ca.InputError(
                f'"{python_module}" is not one of contact_app\'s processes, and --safe refuses to '
                "import a module from the case folder, the working directory or sys.path\n"
                f"  where:    {item.Where(key)}\n"
                f"  expected: one of {', '.join(known)} (or a contact process with "
                '"kratos_module": "KratosMultiphysics.ContactStructuralMechanicsApplication")\n'
                "  fix:      run without --safe only if you trust the code of this case folder"
                + (f" ({hint})" if hint else "")
            )
        folders = [os.getcwd()] + ([str(self.paths.base_dir)] if self.paths.base_dir else [])
        added = [f for f in folders if f not in sys.path]
        sys.path[:0] = added
        try:
            return _import(python_module)
        finally:
            for folder in added:
                sys.path.remove(folder)

    @staticmethod
    def _UnknownModule(
        item: Parameters, key: str, python_module: str, package: str
    ) -> ca.InputError:
        known = _package_modules(package)
        listing = ", ".join(known) if known else "(none yet)"
        hint = suggest(python_module, known)
        return ca.InputError(
            f'unknown process module "{quote(python_module)}"\n  where:    {item.Where(key)}\n'
            f"  expected: one of {listing}" + (f"\n  fix:      {hint}" if hint else "")
        )

    @staticmethod
    def _CheckFactory(item: Parameters, module: ModuleType) -> ModuleType:
        if not callable(getattr(module, "Factory", None)):
            raise error(
                item,
                None,
                f'the module "{module.__name__}" has no Factory(settings, model) function',
                "a process module",
            )
        return module

    # -- creation --

    def _ResolvePaths(self, settings: Parameters) -> None:
        if not settings.IsSubParameter():
            return
        for key in INPUT_PATH_KEYS + OUTPUT_PATH_KEYS:
            if settings.Has(key) and settings[key].IsString() and settings[key].GetString():
                value = settings[key].GetString()
                if key in INPUT_PATH_KEYS:
                    resolved = self.paths.input_path(value, settings.Where(key), "file")
                else:
                    resolved = self.paths.output_path(value)
                if resolved != value:
                    settings[key].SetString(resolved)

    def CreateProcess(self, item: Parameters) -> Any | None:
        """Create one process (None for a skipped descriptor)."""
        module = self.ResolveModule(item)
        if module is None:
            return None
        if not item.Has("Parameters"):
            item.AddValue("Parameters", {})
        convert_legacy_keys(item["Parameters"], "process")  # mesh_id
        self._ResolvePaths(item["Parameters"])
        factory: Callable[[Parameters, ca.Model], Any] = module.Factory
        return factory(item, self.model)

    def ConstructListOfProcesses(self, process_list: Parameters) -> list[Any]:
        """Create the processes of one list, in order."""
        if not process_list.IsArray():
            raise error(
                process_list, None, "a process list is not an array", "[ {descriptor}, ... ]"
            )
        created = (self.CreateProcess(item) for item in process_list)
        return [process for process in created if process is not None]
