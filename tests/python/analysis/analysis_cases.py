"""Helpers of the analysis tests: the data cases, their analytic results, running the CLI."""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

import contact_app as ca

DATA = Path(__file__).parent / "data"

# Material of both cases (plate_materials.json, bar_materials.json); plane strain, thickness 1.
YOUNG, POISSON, DENSITY = 1000.0, 0.3, 1.0


def solver_settings(
    solver_type: str | None, domain_size: int, time_step: float, /, **changes: Any
) -> dict[str, Any]:
    """``solver_settings`` of a "Structure" built in Python, then ``changes`` (keys in order)."""
    settings: dict[str, Any] = {} if solver_type is None else {"solver_type": solver_type}
    settings |= {
        "model_part_name": "Structure",
        "domain_size": domain_size,
        "model_import_settings": {"input_type": "use_input_model_part"},
        "time_stepping": {"time_step": time_step},
    }
    settings.update(changes)
    return settings


def node_coordinates(mdpa: Path) -> dict[int, tuple[float, float]]:
    """Read the nodes of an mdpa file: id -> (x, y)."""
    model = ca.Model()
    part = model.CreateModelPart("Nodes")
    ca.ModelPartIO(str(mdpa)).ReadModelPart(part)
    return {node.Id: (node.X0, node.Y0) for node in part.Nodes}


def plate_displacements(load: float) -> tuple[float, float]:
    """Uniform strains (εxx, εyy) of the plane-strain plate under a line load per current length.

    The right edge shrinks to H(1 + εyy), so the force is q·H(1 + εyy) and σxx = q(1 + εyy) with
    εyy = -ν(1+ν)σxx/E: σxx = q / (1 + q ν(1+ν)/E).
    """
    compliance = POISSON * (1.0 + POISSON) / YOUNG
    stress = load / (1.0 + compliance * load)
    return (1.0 - POISSON**2) / YOUNG * stress, -compliance * stress


def plate_static_results(times: list[float]) -> dict[str, Any]:
    """Reference JSON of plate_static_parameters.json (LINE_LOAD = 2t)."""
    results: dict[str, Any] = {"TIME": times}
    nodes = node_coordinates(DATA / "plate.mdpa")
    for node_id, (x, y) in nodes.items():
        columns: dict[str, list[float]] = {"DISPLACEMENT_X": [], "DISPLACEMENT_Y": []}
        for time in times:
            exx, eyy = plate_displacements(2.0 * time)
            columns["DISPLACEMENT_X"].append(exx * x)
            columns["DISPLACEMENT_Y"].append(eyy * y)
        results[f"NODE_{node_id}"] = columns
    return results


def bossak_oscillator(
    mass: float, stiffness: float, force: float, dt: float, steps: int, alpha_m: float = -0.3
) -> list[tuple[float, float, float]]:
    """(u, v, a) after each step of the Bossak scheme for m ü + k u = F, from rest (a0 = 0)."""
    beta, gamma = (1.0 - alpha_m) ** 2 * 0.25, 0.5 - alpha_m
    c0, c1, c2 = 1.0 / (beta * dt**2), gamma / (beta * dt), 1.0 / (beta * dt)
    c3, c4, c5 = 1.0 / (2.0 * beta) - 1.0, gamma / beta - 1.0, dt / 2.0 * (gamma / beta - 2.0)
    u = v = a = 0.0
    history = []
    for _ in range(steps):
        # m[(1-αm) a_{n+1} + αm a_n] + k u_{n+1} = F with a_{n+1} = c0 Δu - c2 v_n - c3 a_n
        rhs = force - mass * ((1.0 - alpha_m) * (-c0 * u - c2 * v - c3 * a) + alpha_m * a)
        u_new = rhs / (mass * (1.0 - alpha_m) * c0 + stiffness)
        a_new = c0 * (u_new - u) - c2 * v - c3 * a
        v_new = c1 * (u_new - u) - c4 * v - c5 * a
        u, v, a = u_new, v_new, a_new
        history.append((u, v, a))
    return history


def bar_constants() -> tuple[float, float, float]:
    """(mass, stiffness, force) of the one-element bar's stretching mode u_x = u·x.

    Plane strain with u_y = 0: strain energy ½ C11 u² (unit square, t = 1), consistent-mass kinetic
    energy ½ (ρ/3) u̇², line load 10 on the unit right edge.
    """
    c11 = YOUNG * (1.0 - POISSON) / ((1.0 + POISSON) * (1.0 - 2.0 * POISSON))
    return DENSITY / 3.0, c11, 10.0


def bar_dynamic_results(dt: float = 0.01, end_time: float = 0.05) -> dict[str, Any]:
    """Reference JSON of bar_dynamic_parameters.json (nodes 2 and 3 move together)."""
    steps = math.ceil(end_time / dt - 1e-9)
    history = bossak_oscillator(*bar_constants(), dt=dt, steps=steps)
    columns = {
        "DISPLACEMENT_X": [h[0] for h in history],
        "VELOCITY_X": [h[1] for h in history],
        "ACCELERATION_X": [h[2] for h in history],
    }
    return {"TIME": [dt * (i + 1) for i in range(steps)], "NODE_2": columns, "NODE_3": columns}


def load(path: Path) -> dict[str, Any]:
    """Read a JSON file."""
    return json.loads(path.read_text())


Edit = Callable[[dict[str, Any]], None]
