r"""Kratos oracle: reaction histories of the 2D ironing example (examples/ironing_2d).

Runs Kratos on the example's own ProjectParameters.json, materials.json and the .mdpa written by its
make_mesh.py (copied into a scratch folder) and records after every step the REACTION summed over
DISPLACEMENT_die_top (the force the die's holder applies to the die: +x drags it along the slide,
-y presses it down), the REACTION summed over the slab's base, the Newton iterations and the numbers
of ACTIVE and SLIP slave nodes. Writes ``tests/python/examples/data/ironing_2d_<variant>.json``.
When Kratos stops with an error, the fixture keeps the steps it finished and the error
(``failure``).

Variants: ``alm`` is the example unchanged; ``penalty`` and ``alm_frictionless`` change
``mortar_type``, the contact process module and ``contact_type`` only. Output processes are dropped.
Kratos needs KratosConstitutiveLawsApplication for HyperElasticPlaneStrain2DLaw (the same name as
ours); otherwise it reads the files as they are. ``--end-time`` and ``--contact-setting`` are for
trial runs and write no fixture.

Usage (in its own virtual environment, never a dependency of contact_app)::

    python3 -m venv /tmp/kratos_venv
    /tmp/kratos_venv/bin/pip install KratosMultiphysics KratosStructuralMechanicsApplication \
        KratosContactStructuralMechanicsApplication KratosLinearSolversApplication \
        KratosConstitutiveLawsApplication
    /tmp/kratos_venv/bin/python scripts/oracle/ironing_2d.py [--refinement 1] \
        [--variant alm|penalty|alm_frictionless]
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
import KratosMultiphysics.ConstitutiveLawsApplication  # noqa: F401  (HyperElasticPlaneStrain2DLaw)
import KratosMultiphysics.ContactStructuralMechanicsApplication  # noqa: F401
import KratosMultiphysics.StructuralMechanicsApplication  # noqa: F401
from KratosMultiphysics.StructuralMechanicsApplication.structural_mechanics_analysis import (
    StructuralMechanicsAnalysis,
)

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "ironing_2d"
OUT = ROOT / "tests" / "python" / "examples" / "data"
#: Fixture suffix -> (mortar_type, contact process module, contact_type). "alm" is the example as
#: it is; the others change these three settings only.
VARIANTS = {
    "alm": ("ALMContactFrictional", "alm_contact_process", "Frictional"),
    "penalty": ("PenaltyContactFrictional", "penalty_contact_process", "Frictional"),
    "alm_frictionless": ("ALMContactFrictionless", "alm_contact_process", "Frictionless"),
}


def variant_parameters(raw: dict, variant: str) -> dict:
    """``raw`` (a ProjectParameters tree) set to ``variant``, in place; returns it."""
    mortar_type, module, contact_type = VARIANTS[variant]
    raw["solver_settings"]["contact_settings"]["mortar_type"] = mortar_type
    process = raw["processes"]["contact_process_list"][0]
    process["python_module"] = module
    process["Parameters"]["contact_type"] = contact_type
    return raw


def _make_mesh():
    spec = importlib.util.spec_from_file_location("ironing_2d_make_mesh", EXAMPLE / "make_mesh.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up there
    spec.loader.exec_module(module)
    return module


def _sum(part, variable) -> float:
    return float(sum(node.GetSolutionStepValue(variable) for node in part.Nodes))


class _Recording(StructuralMechanicsAnalysis):
    """The Kratos analysis, recording the reactions and the contact state after every step."""

    def __init__(self, model, parameters) -> None:
        super().__init__(model, parameters)
        self.history: list[dict] = []

    def FinalizeSolutionStep(self) -> None:  # noqa: N802 - Kratos name
        super().FinalizeSolutionStep()
        main = self.model.GetModelPart("Structure")
        top = main.GetSubModelPart("DISPLACEMENT_die_top")
        base = main.GetSubModelPart("DISPLACEMENT_slab_base")
        slave = [n for n in main.GetSubModelPart("Contact_Slave").Nodes if n.Is(KM.SLAVE)]
        self.history.append(
            {
                "time": main.ProcessInfo[KM.TIME],
                "iterations": main.ProcessInfo[KM.NL_ITERATION_NUMBER],
                "die_reaction_x": _sum(top, KM.REACTION_X),
                "die_reaction_y": _sum(top, KM.REACTION_Y),
                "base_reaction_x": _sum(base, KM.REACTION_X),
                "base_reaction_y": _sum(base, KM.REACTION_Y),
                "die_top_displacement_x": next(iter(top.Nodes)).GetSolutionStepValue(
                    KM.DISPLACEMENT_X
                ),
                "active": sum(n.Is(KM.ACTIVE) for n in slave),
                "slip": sum(n.Is(KM.ACTIVE) and n.Is(KM.SLIP) for n in slave),
            }
        )


def run(refinement: int, variant: str, end_time: float | None, contact_settings: dict) -> dict:
    """Run the example in a scratch folder; return the fixture."""
    raw = variant_parameters(json.loads((EXAMPLE / "ProjectParameters.json").read_text()), variant)
    raw["solver_settings"]["contact_settings"].update(contact_settings)
    raw["output_processes"] = {}
    if end_time is not None:
        raw["problem_data"]["end_time"] = end_time
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch)
        shutil.copy(EXAMPLE / "materials.json", folder / "materials.json")
        mdpa = folder / "ironing_2d.mdpa"
        _make_mesh().write_mesh(mdpa, refinement)
        digest = hashlib.sha256(mdpa.read_bytes()).hexdigest()
        previous = Path.cwd()
        os.chdir(folder)
        failure = None
        try:
            analysis = _Recording(KM.Model(), KM.Parameters(json.dumps(raw)))
            start = time.perf_counter()
            try:
                analysis.Run()
            except RuntimeError as error:  # the oracle's own failure is a result too
                main = analysis.model.GetModelPart("Structure")
                failure = {
                    "step": main.ProcessInfo[KM.STEP],
                    "time": main.ProcessInfo[KM.TIME],
                    "message": str(error).strip().splitlines()[:2],
                }
            elapsed = time.perf_counter() - start
        finally:
            os.chdir(previous)
    return {
        "case": "examples/ironing_2d",
        "kratos": importlib.metadata.version("KratosMultiphysics"),
        "kratos_contact": importlib.metadata.version("KratosContactStructuralMechanicsApplication"),
        "variant": variant,
        "mortar_type": VARIANTS[variant][0],
        "refinement": refinement,
        "mdpa_sha256": digest,
        "end_time": raw["problem_data"]["end_time"],
        "time_step": raw["solver_settings"]["time_stepping"]["time_step"],
        "wall_time": elapsed,
        "failure": failure,
        "history": analysis.history,
    }


def main() -> int:
    """Run one variant and write its fixture."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--refinement", type=int, default=1)
    parser.add_argument("--variant", default="alm", choices=sorted(VARIANTS))
    parser.add_argument("--end-time", type=float, help="stop early (trial runs; no fixture)")
    parser.add_argument(
        "--contact-setting",
        action="append",
        default=[],
        metavar="KEY=JSON",
        help="override a contact_settings entry (trial runs; no fixture)",
    )
    args = parser.parse_args()
    overrides = {
        key: json.loads(value)
        for key, value in (item.split("=", 1) for item in args.contact_setting)
    }
    result = run(args.refinement, args.variant, args.end_time, overrides)
    for step in result["history"]:
        print(
            f"t = {step['time']:.3f}: {step['iterations']:2d} it, "
            f"Fx = {step['die_reaction_x']:+.6e}, Fy = {step['die_reaction_y']:+.6e}, "
            f"active {step['active']}, slip {step['slip']}"
        )
    if result["failure"]:
        print(f"Kratos stopped: {result['failure']}")
    if args.end_time is not None or overrides:
        return 0
    name = f"ironing_2d_{args.variant}"
    if args.refinement != 1:
        name += f"_refinement_{args.refinement}"
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / f"{name}.json").write_text(json.dumps(result, indent=1) + "\n")
    print(f"wrote {OUT / name}.json ({result['wall_time']:.1f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
