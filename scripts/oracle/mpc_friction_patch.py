"""What Kratos's MPC frictional contact does, measured on a 3D press-and-shear patch.

The reference suite has no MPC friction case small enough to read its behaviour off, so this
script builds one: a lower hexahedral block 2 x 2 x 1 (4 x 4 x 1 elements, so that the interface
matches the upper block node for node) fixed at its base, an upper block 1 x 1 x 0.5 (2 x 2 x 1
elements) centred on it, E = 1e7, nu = 0.3, linear elastic. The top face of the upper block is
guided: x and y prescribed, z free. Step 1 presses it with SURFACE_LOAD 10 (N = 10); steps 2..5
shift its top face in x (two small shifts that a stick state carries, then two that must slip with
mu = 0.3). Every step records the base reactions (F_t = |R_x|, N = |R_z|), per slave node ACTIVE,
SLIP, CONTACT_FORCE, NORMAL/TANGENTIAL_CONTACT_STRESS and the x displacement of the slave node
against the master node under it.

Runs: the MPC route (``mpc_contact_process``, contact_type "Frictional") with mu given in the
process only, in the materials only, in both (materials 0.1, process 0.3) and nowhere, to find
where mu comes from and which source wins; the same patch with ``ALMContactFrictional`` for
comparison. The case files are written to a temporary folder, run with the installed Kratos, and
the numbers go to ``tests/python/contact/data/kratos_oracle/{mpc,alm}_frictional_3d_patch.json``.

Usage (the separate virtual environment of generate_kratos_fixtures.py)::

    /tmp/kratos_venv/bin/python scripts/oracle/mpc_friction_patch.py [--keep DIR]
"""

from __future__ import annotations

import argparse
import importlib.metadata
import json
import os
import sys
import tempfile
from pathlib import Path

import KratosMultiphysics as KM  # the oracle, only in its own environment
import KratosMultiphysics.ContactStructuralMechanicsApplication  # noqa: F401
import KratosMultiphysics.StructuralMechanicsApplication  # noqa: F401
from KratosMultiphysics.StructuralMechanicsApplication.structural_mechanics_analysis import (
    StructuralMechanicsAnalysis,
)

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "tests" / "python" / "contact" / "data" / "kratos_oracle"
sys.path.insert(0, str(ROOT / "tests" / "python"))
from process_descriptors import hold_displacement  # noqa: E402  (tests/python/)

MU = 0.3
PRESSURE = 10.0
#: Top-face x shift per step (step 1 presses only): two stick steps, then two slip steps.
TOP_UX = [0.0, 1.0e-7, 2.0e-7, 1.0e-5, 1.0e-4]
#: (label, mu in the materials, mu in the process) of the MPC runs.
MU_SOURCES = [
    ("mu_in_process", None, MU),
    ("mu_in_materials", MU, 0.0),
    ("materials_0.1_process_0.3", 0.1, MU),
    ("mu_0.05_in_process", None, 0.05),
    ("no_mu", None, 0.0),
]
#: (label, mu in the materials, mu in the process, interface given as conditions) of the ALM runs.
ALM_RUNS = [
    ("mu_in_process", None, MU, True),
    ("mu_in_materials", MU, 0.0, True),
    ("mu_in_materials_node_interface", MU, 0.0, False),
]


def _grid(x0: float, z0: float, n: int, h: float, dz: float, first_id: int) -> dict:
    """Node ids of a structured block with n x n x 1 hexahedra; (i, j, k) -> (id, x, y, z)."""
    nodes = {}
    next_id = first_id
    for k in range(2):
        for j in range(n + 1):
            for i in range(n + 1):
                nodes[i, j, k] = (next_id, x0 + i * h, x0 + j * h, z0 + k * dz)
                next_id += 1
    return nodes


def _hexahedra(nodes: dict, n: int) -> list[list[int]]:
    cells = []
    for j in range(n):
        for i in range(n):
            quad = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
            cells.append([nodes[a, b, k][0] for k in (0, 1) for a, b in quad])
    return cells


def _faces(nodes: dict, n: int, k: int, outward_up: bool) -> list[list[int]]:
    """Quadrilaterals of layer k ordered so that their normal points outward (+z or -z)."""
    faces = []
    for j in range(n):
        for i in range(n):
            quad = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
            if not outward_up:
                quad = [quad[0], quad[3], quad[2], quad[1]]
            faces.append([nodes[a, b, k][0] for a, b in quad])
    return faces


def _sub_model_part(name: str, nodes, elements=(), conditions=()) -> str:
    def block(kind: str, ids) -> str:
        body = "".join(f"        {i}\n" for i in sorted(ids))
        return f"    Begin SubModelPart{kind}\n{body}    End SubModelPart{kind}\n"

    return (
        f"Begin SubModelPart {name}\n"
        + block("Nodes", nodes)
        + block("Elements", elements)
        + block("Conditions", conditions)
        + "End SubModelPart\n\n"
    )


def write_mdpa(path: Path, interface_conditions: bool = True) -> dict[int, int]:
    """Write the two-block mesh; returns slave node id -> id of the master node under it.

    With ``interface_conditions`` the contact faces are SurfaceCondition3D4N of property 0 (as in
    the reference MPC cases); without, the contact parts are node sets and the contact process
    generates the faces itself (as in the reference ALM cases), which changes where mu is read.
    """
    lower = _grid(0.0, 0.0, 4, 0.5, 1.0, 1)
    upper = _grid(0.5, 1.0, 2, 0.5, 0.5, 1 + len(lower))
    text = "Begin ModelPartData\nEnd ModelPartData\n\nBegin Properties 0\nEnd Properties\n\n"
    text += "Begin Nodes\n"
    for node_id, x, y, z in sorted([*lower.values(), *upper.values()]):
        text += f"    {node_id} {x:.6f} {y:.6f} {z:.6f}\n"
    text += "End Nodes\n\n"
    lower_cells, upper_cells = _hexahedra(lower, 4), _hexahedra(upper, 2)
    text += "Begin Elements SmallDisplacementElement3D8N\n"
    for element_id, cell in enumerate([*lower_cells, *upper_cells], start=1):
        text += f"    {element_id} 0 " + " ".join(map(str, cell)) + "\n"
    text += "End Elements\n\n"
    master = _faces(lower, 4, 1, outward_up=True)
    slave = _faces(upper, 2, 0, outward_up=False)
    load = _faces(upper, 2, 1, outward_up=True)
    ids = iter(range(1, 1 + len(master) + len(slave) + len(load)))
    numbered = {
        name: [(next(ids), face) for face in faces]
        for name, faces in (("master", master), ("slave", slave), ("load", load))
    }
    blocks = [("SurfaceLoadCondition3D4N", ("load",))]
    if interface_conditions:
        blocks.insert(0, ("SurfaceCondition3D4N", ("master", "slave")))
    else:
        numbered["master"], numbered["slave"] = [], []
    for kind, names in blocks:
        text += f"Begin Conditions {kind}\n"
        for name in names:
            for condition_id, face in numbered[name]:
                text += f"    {condition_id} 0 " + " ".join(map(str, face)) + "\n"
        text += "End Conditions\n\n"

    def layer(nodes, k):
        return [v[0] for (i, j, kk), v in nodes.items() if kk == k]

    n_lower = len(lower_cells)
    text += _sub_model_part("Parts_Lower", [v[0] for v in lower.values()], range(1, n_lower + 1))
    text += _sub_model_part(
        "Parts_Upper", [v[0] for v in upper.values()], range(n_lower + 1, n_lower + 5)
    )
    text += _sub_model_part("Base", layer(lower, 0))
    text += _sub_model_part("Top", layer(upper, 1))
    text += _sub_model_part("Load_Top", layer(upper, 1), (), [c for c, _ in numbered["load"]])
    text += _sub_model_part(
        "Contact_Part_Slave", layer(upper, 0), (), [c for c, _ in numbered["slave"]]
    )
    text += _sub_model_part(
        "Contact_Part_Master", layer(lower, 1), (), [c for c, _ in numbered["master"]]
    )
    path.write_text(text)
    under = {(x, y): node_id for node_id, x, y, z in lower.values() if z == 1.0}
    return {node_id: under[x, y] for node_id, x, y, z in upper.values() if z == 1.0}


def materials(mu: float | None) -> dict:
    """Both blocks linear elastic; FRICTION_COEFFICIENT only when mu is given."""
    variables = {"YOUNG_MODULUS": 1.0e7, "POISSON_RATIO": 0.3, "DENSITY": 1.0}
    if mu is not None:
        variables["FRICTION_COEFFICIENT"] = mu
    return {
        "properties": [
            {
                "model_part_name": f"Structure.{part}",
                "properties_id": pid,
                "Material": {
                    "constitutive_law": {"name": "LinearElastic3DLaw"},
                    "Variables": variables,
                    "Tables": {},
                },
            }
            for pid, part in ((1, "Parts_Lower"), (2, "Parts_Upper"))
        ]
    }


def parameters(route: str, mu_process: float) -> dict:
    """Static, one step per entry of TOP_UX; route "mpc" or "alm"."""
    steps = len(TOP_UX)
    guides = [
        hold_displacement(
            "Top", [True, True, False], [ux, 0.0, None], interval=[step + 0.5, step + 1.5]
        )
        for step, ux in enumerate(TOP_UX)
    ]
    contact = {
        "model_part_name": "Structure",
        "contact_model_part": {"0": ["Contact_Part_Slave", "Contact_Part_Master"]},
        "assume_master_slave": {"0": ["Contact_Part_Slave"]},
        "contact_type": "Frictional",
        "friction_coefficients": {"0": mu_process},
    }
    solver = {
        "model_part_name": "Structure",
        "domain_size": 3,
        "solver_type": "Static",
        "echo_level": 0,
        "analysis_type": "non_linear",
        "time_stepping": {"time_step": 1.0},
        "model_import_settings": {"input_type": "mdpa", "input_filename": "patch"},
        "material_import_settings": {"materials_filename": "materials.json"},
        "displacement_relative_tolerance": 1.0e-6,
        "displacement_absolute_tolerance": 1.0e-12,
        "residual_relative_tolerance": 1.0e-6,
        "residual_absolute_tolerance": 1.0e-12,
        "max_iteration": 30,
        "linear_solver_settings": {"solver_type": "skyline_lu_factorization"},
    }
    if route == "mpc":
        solver["convergence_criterion"] = "residual_criterion"
        solver["mpc_contact_settings"] = {"contact_type": "Frictional"}
        process = "mpc_contact_process"
    else:
        solver["convergence_criterion"] = "contact_residual_criterion"
        solver["contact_settings"] = {"mortar_type": "ALMContactFrictional"}
        process = "alm_contact_process"
    return {
        "problem_data": {
            "problem_name": f"{route}_frictional_3d_patch",
            "parallel_type": "OpenMP",
            "start_time": 0.0,
            "end_time": float(steps),
            "echo_level": 0,
        },
        "solver_settings": solver,
        "processes": {
            "constraints_process_list": [
                hold_displacement(
                    "Base", [True, True, True], [0.0, 0.0, 0.0], interval=[0.0, "End"]
                ),
                *guides,
            ],
            "loads_process_list": [
                {
                    "python_module": "assign_vector_by_direction_to_condition_process",
                    "kratos_module": "KratosMultiphysics",
                    "Parameters": {
                        "model_part_name": "Structure.Load_Top",
                        "variable_name": "SURFACE_LOAD",
                        "modulus": PRESSURE,
                        "direction": [0.0, 0.0, -1.0],
                        "interval": [0.0, "End"],
                    },
                }
            ],
            "contact_process_list": [
                {
                    "python_module": process,
                    "kratos_module": "KratosMultiphysics.ContactStructuralMechanicsApplication",
                    "Parameters": contact,
                }
            ],
        },
    }


def _nodal(node, name: str):
    """A nodal value, historical if the variable is stored per step, else the non-historical one."""
    variable = KM.KratosGlobals.GetVariable(name)
    if node.SolutionStepsDataHas(variable):
        value = node.GetSolutionStepValue(variable)
    elif node.Has(variable):
        value = node.GetValue(variable)
    else:
        return None
    return [float(v) for v in value] if hasattr(value, "__len__") else float(value)


def _sum(nodes, variable) -> float:
    return float(sum(n.GetSolutionStepValue(variable) for n in nodes))


class _Recorder(StructuralMechanicsAnalysis):
    """Keeps the state of the patch after every converged step."""

    def __init__(self, model, settings, under: dict[int, int]):
        super().__init__(model, settings)
        self.under = under
        self.steps: list[dict] = []
        self.converged: bool | None = None

    def Initialize(self):
        """Wrap the solver's step so that each record says whether Newton converged."""
        super().Initialize()
        solver = self._GetSolver()
        solve = solver.SolveSolutionStep

        def solve_and_keep():
            self.converged = bool(solve())
            return self.converged

        solver.SolveSolutionStep = solve_and_keep

    def FinalizeSolutionStep(self):
        super().FinalizeSolutionStep()
        main = self.model.GetModelPart("Structure")
        step = main.ProcessInfo[KM.STEP]
        base = list(main.GetSubModelPart("Base").Nodes)
        top = list(main.GetSubModelPart("Top").Nodes)
        reaction = {c: _sum(base, getattr(KM, f"REACTION_{c}")) for c in "XYZ"}
        slaves = {}
        for node in main.GetSubModelPart("Contact_Part_Slave").Nodes:
            master = main.GetNode(self.under[node.Id])
            entry = {
                "ACTIVE": node.Is(KM.ACTIVE),
                "SLIP": node.Is(KM.SLIP),
                "DISPLACEMENT_X": node.GetSolutionStepValue(KM.DISPLACEMENT_X),
                "MASTER_NODE": master.Id,
                "MASTER_DISPLACEMENT_X": master.GetSolutionStepValue(KM.DISPLACEMENT_X),
            }
            for name in (
                "CONTACT_FORCE",
                "NORMAL_CONTACT_STRESS",
                "TANGENTIAL_CONTACT_STRESS",
                "AUGMENTED_NORMAL_CONTACT_PRESSURE",
                "AUGMENTED_TANGENT_CONTACT_PRESSURE",
                "WEIGHTED_SLIP",
                "FRICTION_COEFFICIENT",
            ):
                value = _nodal(node, name)
                if value is not None:
                    entry[name] = value
            slaves[f"NODE_{node.Id}"] = entry
        constraints = list(main.MasterSlaveConstraints)
        # The coefficient the contact actually uses: the slave nodes' FRICTION_COEFFICIENT.
        mu = max((s.get("FRICTION_COEFFICIENT") or 0.0) for s in slaves.values())
        normal = abs(reaction["Z"])
        self.steps.append(
            {
                "step": step,
                "time": main.ProcessInfo[KM.TIME],
                "converged": self.converged,
                "iterations": main.ProcessInfo[KM.NL_ITERATION_NUMBER],
                "top_ux": TOP_UX[step - 1],
                "reaction_base": reaction,
                "reaction_top": {c: _sum(top, getattr(KM, f"REACTION_{c}")) for c in "XYZ"},
                "mu_effective": mu,
                "ft_over_mu_n": abs(reaction["X"]) / (mu * normal) if mu * normal > 0.0 else None,
                "master_slave_constraints": len(constraints),
                "active_constraints": sum(1 for c in constraints if c.IsActive()),
                "slave": slaves,
            }
        )


def run(
    folder: Path,
    route: str,
    mu_materials: float | None,
    mu_process: float,
    interface_conditions: bool = True,
) -> dict:
    """Run one configuration in ``folder``; per-step records plus where mu ended up."""
    folder.mkdir(parents=True, exist_ok=True)
    under = write_mdpa(folder / "patch.mdpa", interface_conditions)
    (folder / "materials.json").write_text(json.dumps(materials(mu_materials), indent=1))
    raw = parameters(route, mu_process)
    (folder / "parameters.json").write_text(json.dumps(raw, indent=1))
    cwd = os.getcwd()
    os.chdir(folder)
    try:
        model = KM.Model()
        analysis = _Recorder(model, KM.Parameters(json.dumps(raw)), under)
        analysis.Run()
    finally:
        os.chdir(cwd)
    main = model.GetModelPart("Structure")
    contact_properties = {}
    if main.HasSubModelPart("Contact"):
        for prop in main.GetSubModelPart("Contact").GetProperties():
            has = prop.Has(KM.FRICTION_COEFFICIENT)
            contact_properties[str(prop.Id)] = prop[KM.FRICTION_COEFFICIENT] if has else None
    return {
        "mu_materials": mu_materials,
        "mu_process": mu_process,
        "interface": "conditions" if interface_conditions else "node sets",
        "contact_properties_friction_coefficient": contact_properties,
        "steps": analysis.steps,
    }


def _summary(result: dict) -> list[str]:
    lines = []
    for step in result["steps"]:
        states = sorted(
            {(s["ACTIVE"], s["SLIP"]) for s in step["slave"].values()}, key=lambda t: (t[0], t[1])
        )
        gap = max(
            abs(s["DISPLACEMENT_X"] - s["MASTER_DISPLACEMENT_X"]) for s in step["slave"].values()
        )
        ratio = "-" if step["ft_over_mu_n"] is None else f"{step['ft_over_mu_n']:.4f}"
        lines.append(
            f"  step {step['step']} ux {step['top_ux']:.1e}: R {step['reaction_base']['X']:+.4e} "
            f"{step['reaction_base']['Z']:+.4e}  mu {step['mu_effective']}  Ft/(mu N) {ratio}  "
            f"conv {step['converged']} ({step['iterations']})  (ACTIVE, SLIP) {states}  "
            f"max|u_s - u_m| {gap:.3e}  constraints {step['active_constraints']}"
            f"/{step['master_slave_constraints']}"
        )
    return lines


def main() -> int:
    """Run every configuration and write the two fixtures."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--keep", type=Path, help="write the case folders here (kept)")
    args = parser.parse_args()
    version = importlib.metadata.version("KratosMultiphysics")
    with tempfile.TemporaryDirectory() as scratch:
        base = args.keep or Path(scratch)
        mpc_runs = {}
        for label, mu_materials, mu_process in MU_SOURCES:
            mpc_runs[label] = run(base / f"mpc_{label}", "mpc", mu_materials, mu_process)
            print(f"mpc {label}", *_summary(mpc_runs[label]), sep="\n")
        alm_runs = {}
        for label, mu_materials, mu_process, conditions in ALM_RUNS:
            alm_runs[label] = run(
                base / f"alm_{label}", "alm", mu_materials, mu_process, conditions
            )
            print(f"alm {label}", *_summary(alm_runs[label]), sep="\n")
    common = {
        "kratos": version,
        "patch": __doc__.split("\n\n")[1].replace("\n", " "),
        "mu": MU,
        "pressure": PRESSURE,
        "top_ux": TOP_UX,
    }
    for route, runs in (("mpc", mpc_runs), ("alm", alm_runs)):
        path = OUT / f"{route}_frictional_3d_patch.json"
        summary = {label: [line.strip() for line in _summary(r)] for label, r in runs.items()}
        document = {**common, "runs": runs, "summary": summary}
        path.write_text(json.dumps(document, indent=1, sort_keys=True) + "\n")
        print(f"wrote {path.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
