r"""Kratos oracle: contact pressure field of the sliding cylinders (issue 17, pressure spikes).

Runs Kratos on ``../shared/kratos_examples/cylinders/source/horizontal_movement_1`` (a copy in a
scratch folder, its parameters unchanged but ``end_time`` and no output processes) and records after
every step, over the ACTIVE slave nodes of the Contact part: their number, the largest and the
median |AUGMENTED_NORMAL_CONTACT_PRESSURE| (and the node holding the largest), the smallest and the
median NODAL_AREA, and the REACTION summed over DISPLACEMENT_FixedBase. Writes
``tests/python/contact/data/kratos_oracle/cylinders_horizontal_movement_1.json`` (``--output`` to
write elsewhere).

Usage (in its own virtual environment, never a dependency of contact_app; the model's
HyperElastic3DLaw lives in KratosConstitutiveLawsApplication)::

    python3 -m venv /tmp/kratos_venv
    /tmp/kratos_venv/bin/pip install KratosMultiphysics==10.4.4 \
        KratosStructuralMechanicsApplication==10.4.4 \
        KratosContactStructuralMechanicsApplication==10.4.4 \
        KratosLinearSolversApplication==10.4.4 KratosConstitutiveLawsApplication==10.4.4
    /tmp/kratos_venv/bin/python scripts/oracle/cylinders_pressure.py [--end-time 0.2]
"""

from __future__ import annotations

import argparse
import hashlib
import importlib.metadata
import importlib.util
import json
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path

import KratosMultiphysics as KM  # the oracle, only in its own environment
import KratosMultiphysics.ConstitutiveLawsApplication  # noqa: F401  (HyperElastic3DLaw)
import KratosMultiphysics.ContactStructuralMechanicsApplication as CSMA
import KratosMultiphysics.StructuralMechanicsApplication  # noqa: F401
from KratosMultiphysics.StructuralMechanicsApplication.structural_mechanics_analysis import (
    StructuralMechanicsAnalysis,
)

ROOT = Path(__file__).resolve().parents[2]
CASE = ROOT.parent / "shared/kratos_examples/cylinders/source/horizontal_movement_1"
OUT = ROOT / "tests/python/contact/data/kratos_oracle/cylinders_horizontal_movement_1.json"


def _record_module():
    """tests/python/contact/contact_pressure_record.py: the record both systems keep."""
    path = ROOT / "tests/python/contact/contact_pressure_record.py"
    spec = importlib.util.spec_from_file_location("contact_pressure_record", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


class _Recording(StructuralMechanicsAnalysis):
    def __init__(self, model, parameters) -> None:
        super().__init__(model, parameters)
        self.history: list[dict] = []
        self.record = _record_module()

    def FinalizeSolutionStep(self) -> None:  # noqa: N802 - Kratos name
        super().FinalizeSolutionStep()
        self.history.append(
            self.record.step_record(
                self.model.GetModelPart("Structure"),
                KM,
                CSMA.AUGMENTED_NORMAL_CONTACT_PRESSURE,
                "DISPLACEMENT_FixedBase",
            )
        )


def run(end_time: float) -> dict:
    """Run the case to ``end_time`` in a scratch copy; return the fixture."""
    raw = json.loads((CASE / "ProjectParameters.json").read_text())
    raw["problem_data"]["end_time"] = end_time
    raw["output_processes"] = {}
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch) / "case"
        shutil.copytree(CASE, folder)
        previous = Path.cwd()
        os.chdir(folder)
        try:
            analysis = _Recording(KM.Model(), KM.Parameters(json.dumps(raw)))
            start = time.perf_counter()
            analysis.Run()
            wall = time.perf_counter() - start
        finally:
            os.chdir(previous)
    return {
        "case": "../shared/kratos_examples/cylinders/source/horizontal_movement_1",
        "kratos": importlib.metadata.version("KratosMultiphysics"),
        "kratos_contact": importlib.metadata.version("KratosContactStructuralMechanicsApplication"),
        "mdpa_sha256": hashlib.sha256((CASE / "cylinders.mdpa").read_bytes()).hexdigest(),
        "end_time": end_time,
        "wall_time": wall,
        "history": analysis.history,
    }


def main() -> int:
    """Command line: run and write the fixture."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--end-time", type=float, default=0.2)
    parser.add_argument("--output", type=Path, default=OUT)
    args = parser.parse_args()
    fixture = run(args.end_time)
    args.output.write_text(json.dumps(fixture, indent=1) + "\n")
    last = fixture["history"][-1]
    print(f"wrote {args.output}: {len(fixture['history'])} steps, last {last}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
