"""Fixtures of the process tests: a small 2D plate with sub model parts and a step driver."""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any

import pytest
from structure_model_part import create_structure

import contact_app as ca
from contact_app.parameters import Parameters
from contact_app.processes.process import Process

# A 2 x 2 plate of unit quadrilaterals: node id -> (x, y); ids grow with x, then y.
PLATE_NODES = {1 + i + 3 * j: (float(i), float(j)) for j in range(3) for i in range(3)}
PLATE_ELEMENTS = {1: [1, 2, 5, 4], 2: [2, 3, 6, 5], 3: [4, 5, 8, 7], 4: [5, 6, 9, 8]}
TOP_CONDITIONS = {1: [9, 8], 2: [8, 7]}  # outward normal +y with Kratos' (dy, -dx) rule


@pytest.fixture
def model() -> ca.Model:
    return ca.Model()


@pytest.fixture
def plate(model: ca.Model) -> ca.ModelPart:
    """Return the plate of :func:`build_plate` in ``model``."""
    return build_plate(model)


def build_plate(model: ca.Model) -> ca.ModelPart:
    """Return "Structure": 4 initialised linear-elastic quads, DOMAIN_SIZE 2, DoFs DISPLACEMENT_X/Y.

    Sub model parts: "Bottom" (nodes 1-3), "Top" (nodes 7-9, line conditions 1-2), "Body"
    (elements and all nodes).
    """
    mp, props = create_structure(model, 2, 200.0, "LinearElasticPlaneStress2DLaw", thickness=1.0)
    for node_id, (x, y) in PLATE_NODES.items():
        node = mp.CreateNewNode(node_id, x, y, 0.0)
        node.AddDof(ca.DISPLACEMENT_X, ca.REACTION_X)
        node.AddDof(ca.DISPLACEMENT_Y, ca.REACTION_Y)
    for element_id, nodes in PLATE_ELEMENTS.items():
        element = mp.CreateNewElement("SmallDisplacementElement2D4N", element_id, nodes, props)
        element.Initialize(mp.ProcessInfo)
    for condition_id, nodes in TOP_CONDITIONS.items():
        mp.CreateNewCondition("LineLoadCondition2D2N", condition_id, nodes, props)
    bottom = mp.CreateSubModelPart("Bottom")
    bottom.AddNodes([1, 2, 3])
    top = mp.CreateSubModelPart("Top")
    top.AddNodes([7, 8, 9])
    top.AddConditions(list(TOP_CONDITIONS))
    body = mp.CreateSubModelPart("Body")
    body.AddNodes(list(PLATE_NODES))
    body.AddElements(list(PLATE_ELEMENTS))
    return mp


def impose_displacement(model_part: ca.ModelPart, time: float) -> None:
    """Stand-in for a solve: u = (0.01 t x, -0.02 t y, 0) on every node (uniform strain)."""
    for node in model_part.Nodes:
        node.SetSolutionStepValue(
            ca.DISPLACEMENT, 0, [0.01 * time * node.X0, -0.02 * time * node.Y0, 0.0]
        )


def descriptor(module: str, parameters: dict[str, Any]) -> Parameters:
    """Return a process descriptor as it appears in ProjectParameters.json."""
    return Parameters(
        {
            "python_module": module,
            "kratos_module": "KratosMultiphysics",
            "process_name": "Test",
            "Parameters": parameters,
        },
        "ProjectParameters.json",
        ("processes", "test_list", "[0]"),
    )


def create(module: str, parameters: dict[str, Any], model: ca.Model) -> Any:
    """Import ``contact_app.processes.<module>`` and call its Factory, as the analysis does."""
    import importlib

    factory = importlib.import_module(f"contact_app.processes.{module}").Factory
    return factory(descriptor(module, parameters), model)


def create_on(module: str, model: ca.Model, part: str, variable: str, **settings: Any) -> Any:
    """``create`` the process ``module`` on ``variable`` of the part ``part``, with ``settings``.

    The assignment tests name a part and a variable every time: the other keys are what they vary.
    """
    return create(module, {"model_part_name": part, "variable_name": variable, **settings}, model)


def run_steps(
    model_part: ca.ModelPart,
    processes: Iterable[Process],
    times: Iterable[float],
    solve: Callable[[float], None] | None = None,
) -> None:
    """Drive the life cycle: ExecuteInitialize, BeforeSolutionLoop, then one step per time."""
    processes = list(processes)
    for process in processes:
        process.ExecuteInitialize()
    for process in processes:
        process.ExecuteBeforeSolutionLoop()
    for time in times:
        model_part.CloneTimeStep(time)
        for process in processes:
            process.ExecuteInitializeSolutionStep()
        if solve is not None:
            solve(time)
        for process in processes:
            process.ExecuteFinalizeSolutionStep()
    for process in processes:
        process.ExecuteFinalize()
