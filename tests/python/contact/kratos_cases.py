"""The Kratos contact cases of ../shared/kratos_cases that the oracle runs and the tests compare.

Plain Python without imports of contact_app or Kratos: imported by the tests as ``kratos_cases``
(pytest puts this folder on ``sys.path``) and by scripts/oracle from this folder.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

CASES_DIR = Path(__file__).resolve().parents[3].parent / "shared" / "kratos_cases"
#: Case name -> path of its files in CASES_DIR, without the "_parameters.json" ending.
CASES = {
    "alm_frictionless_2d_hyper_simple": "ALM_frictionless_contact_test_2D/hyper_simple_patch_test",
    "alm_frictionless_2d_taylor": "ALM_frictionless_contact_test_2D/taylor_patch_test",
    "alm_frictionless_3d_slope": (
        "ALM_frictionless_contact_test_3D/3D_contact_simplest_patch_matching_slope_test"
    ),
    "alm_frictional_2d_hyper_simple": "ALM_frictional_contact_test_2D/hyper_simple_patch_test",
    "penalty_frictionless_2d": "penalty_frictionless_contact_test_2D/hyper_simple_patch_test",
    "penalty_frictional_2d_stick": (
        "penalty_frictional_contact_test_2D/perfect_stick_hyper_simple_patch_test"
    ),
    "mesh_tying_2d": "mesh_tying_test/simple_patch_test_2D",
    "mpc_2d_matching": "mpc_contact_tests/2D_contact_simplest_patch_matching_test",
}


def strip_mesh_id(value: Any) -> Any:
    """Drop keys the current Kratos no longer accepts (mesh_id)."""
    if isinstance(value, dict):
        return {k: strip_mesh_id(v) for k, v in value.items() if k != "mesh_id"}
    if isinstance(value, list):
        return [strip_mesh_id(v) for v in value]
    return value
