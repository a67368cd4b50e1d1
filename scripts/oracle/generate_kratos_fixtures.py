"""Produce reference numbers with the Kratos oracle (PyPI KratosMultiphysics, never a dependency).

Runs each reference case of ../shared/kratos_cases with the installed Kratos and writes the final
values of the variables its ``from_json_check_result_process`` checks to
``tests/python/contact/data/kratos_oracle/<case>.json``. The 2019 result files of the cases
predate later Kratos changes; these fixtures record what the current Kratos computes.

Usage (in a separate virtual environment)::

    python -m venv /tmp/kratos_venv
    /tmp/kratos_venv/bin/pip install KratosMultiphysics KratosStructuralMechanicsApplication \\
        KratosContactStructuralMechanicsApplication KratosLinearSolversApplication
    /tmp/kratos_venv/bin/python scripts/oracle/generate_kratos_fixtures.py
"""

from __future__ import annotations

import importlib.metadata
import json
import os
import sys
from pathlib import Path

import KratosMultiphysics as KM  # noqa: F401  (the oracle, only in its own environment)
import KratosMultiphysics.ContactStructuralMechanicsApplication  # noqa: F401
import KratosMultiphysics.StructuralMechanicsApplication  # noqa: F401
from KratosMultiphysics.StructuralMechanicsApplication.structural_mechanics_analysis import (
    StructuralMechanicsAnalysis,
)

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "tests" / "python" / "contact" / "data" / "kratos_oracle"
sys.path.insert(0, str(ROOT / "tests" / "python" / "contact"))
from kratos_cases import CASES, CASES_DIR, strip_mesh_id  # noqa: E402  (tests/python/contact/)


def run(name: str, case: str, components: bool) -> dict:
    os.chdir(CASES_DIR)
    raw = strip_mesh_id(json.loads(Path(f"{case}_parameters.json").read_text()))
    checks = raw["processes"].pop("json_check_process", [])
    raw.pop("output_processes", None)
    # A direct solver of the core (some cases name solvers of applications not on PyPI).
    raw["solver_settings"]["linear_solver_settings"] = {"solver_type": "skyline_lu_factorization"}
    if components:
        raw["solver_settings"]["contact_settings"]["mortar_type"] = "ALMContactFrictionlessComponents"
        for process in raw["processes"]["contact_process_list"]:
            process["Parameters"]["contact_type"] = "FrictionlessComponents"
    model = KM.Model()
    StructuralMechanicsAnalysis(model, KM.Parameters(json.dumps(raw))).Run()
    values: dict[str, dict[str, float]] = {}
    for check in checks:
        settings = check["Parameters"]
        part = model.GetModelPart(settings["model_part_name"])
        historical = settings.get("historical_value", True)
        for variable_name in settings["check_variables"]:
            variable = KM.KratosGlobals.GetVariable(variable_name)
            for node in part.Nodes:
                value = node.GetSolutionStepValue(variable) if historical else node.GetValue(variable)
                values.setdefault(f"NODE_{node.Id}", {})[variable_name] = float(value)
    return {"case": case, "components": components, "kratos": importlib.metadata.version("KratosMultiphysics"), "values": values}


def main() -> int:
    OUT.mkdir(parents=True, exist_ok=True)
    selected = sys.argv[1:] or list(CASES)
    for name in selected:
        variants = [False, True] if name.startswith("alm_frictionless") else [False]
        for components in variants:
            label = f"{name}_components" if components else name
            try:
                result = run(name, CASES[name], components)
            except Exception as failure:  # report and go on with the other cases
                print(f"{label}: Kratos failed: {failure}", file=sys.stderr)
                continue
            (OUT / f"{label}.json").write_text(json.dumps(result, indent=1, sort_keys=True) + "\n")
            print(f"{label}: {sum(len(v) for v in result['values'].values())} values")
    return 0


if __name__ == "__main__":
    sys.exit(main())
