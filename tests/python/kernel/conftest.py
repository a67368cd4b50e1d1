"""Fixtures of the kernel tests: small model parts built from literal tables."""

from __future__ import annotations

import pytest

import contact_app as ca

# A 2 x 3 rectangle split into two 1 x 3 quadrilaterals: node id -> (x, y).
RECTANGLE_NODES = {
    1: (0.0, 0.0),
    2: (1.0, 0.0),
    3: (2.0, 0.0),
    4: (0.0, 3.0),
    5: (1.0, 3.0),
    6: (2.0, 3.0),
}


@pytest.fixture
def model() -> ca.Model:
    return ca.Model()


@pytest.fixture
def structure(model: ca.Model) -> ca.ModelPart:
    """Return a root model part "Structure" (buffer 2) with historical DISPLACEMENT, REACTION."""
    model_part = model.CreateModelPart("Structure", 2)
    model_part.AddNodalSolutionStepVariable(ca.DISPLACEMENT)
    model_part.AddNodalSolutionStepVariable(ca.REACTION)
    return model_part


@pytest.fixture
def rectangle(structure: ca.ModelPart) -> ca.ModelPart:
    """Return the RECTANGLE_NODES mesh: nodes 1..6 and properties 1, no elements."""
    for node_id, (x, y) in RECTANGLE_NODES.items():
        structure.CreateNewNode(node_id, x, y, 0.0)
    structure.CreateNewProperties(1)
    return structure
