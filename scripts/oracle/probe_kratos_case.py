"""Run one reference case with the Kratos oracle and print the slave-node contact state.

For comparing with contact_app when a case disagrees: λ (LAGRANGE_MULTIPLIER_CONTACT_PRESSURE),
WEIGHTED_GAP, AUGMENTED_NORMAL_CONTACT_PRESSURE, INITIAL_PENALTY and NORMAL of every SLAVE node of
the Contact part, plus SCALE_FACTOR and INITIAL_PENALTY of the ProcessInfo. Same environment as
generate_kratos_fixtures.py (a separate virtual environment with the PyPI Kratos packages).

Usage: /tmp/kratos_venv/bin/python scripts/oracle/probe_kratos_case.py \\
           ALM_frictionless_contact_test_3D/3D_contact_simplest_patch_matching_slope_test \\
           [convergence_criterion]
"""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path

import KratosMultiphysics as KM
import KratosMultiphysics.ContactStructuralMechanicsApplication as CSMA
import KratosMultiphysics.StructuralMechanicsApplication  # noqa: F401
from KratosMultiphysics.StructuralMechanicsApplication.structural_mechanics_analysis import (
    StructuralMechanicsAnalysis,
)

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tests" / "python" / "contact"))
from kratos_cases import CASES_DIR, strip_mesh_id  # noqa: E402  (tests/python/contact/)


def main() -> int:
    case = sys.argv[1]
    os.chdir(CASES_DIR)
    raw = strip_mesh_id(json.loads(Path(f"{case}_parameters.json").read_text()))
    raw["processes"].pop("json_check_process", None)
    raw.pop("output_processes", None)
    raw["solver_settings"]["linear_solver_settings"] = {"solver_type": "skyline_lu_factorization"}
    if len(sys.argv) > 2:
        raw["solver_settings"]["convergence_criterion"] = sys.argv[2]
    model = KM.Model()
    StructuralMechanicsAnalysis(model, KM.Parameters(json.dumps(raw))).Run()
    main_part = model.GetModelPart("Structure")
    info = main_part.ProcessInfo
    print("SCALE_FACTOR", info[KM.SCALE_FACTOR], "INITIAL_PENALTY", info[KM.INITIAL_PENALTY])
    for node in main_part.GetSubModelPart("Contact").Nodes:
        if node.Is(KM.SLAVE):
            print(
                node.Id,
                node.GetSolutionStepValue(CSMA.LAGRANGE_MULTIPLIER_CONTACT_PRESSURE),
                node.GetSolutionStepValue(CSMA.WEIGHTED_GAP),
                node.GetValue(CSMA.AUGMENTED_NORMAL_CONTACT_PRESSURE),
                node.GetValue(KM.INITIAL_PENALTY),
                list(node.GetSolutionStepValue(KM.NORMAL)),
            )
    return 0


if __name__ == "__main__":
    sys.exit(main())
