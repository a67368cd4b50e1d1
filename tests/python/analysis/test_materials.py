"""Materials JSON: prefixes, value kinds, tables, assignment to elements and conditions, errors."""

from __future__ import annotations

import json
import logging
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import contact_app as ca
from contact_app.analysis import MaterialsReader, ReadMaterials


def _model() -> ca.Model:
    """Structure with Parts_a (element 1 + condition 1) and Parts_b (element 2), properties 0."""
    model = ca.Model()
    part = model.CreateModelPart("Structure")
    for node_id, (x, y) in enumerate([(0, 0), (1, 0), (1, 1), (0, 1), (2, 0), (2, 1)], start=1):
        part.CreateNewNode(node_id, float(x), float(y), 0.0)
    props = part.CreateNewProperties(0)
    a, b = part.CreateSubModelPart("Parts_a"), part.CreateSubModelPart("Parts_b")
    a.CreateNewElement("SmallDisplacementElement2D4N", 1, [1, 2, 3, 4], props)
    a.CreateNewCondition("LineLoadCondition2D2N", 1, [2, 3], props)
    b.CreateNewElement("SmallDisplacementElement2D4N", 2, [2, 5, 6, 3], props)
    return model


def _block(**material: Any) -> dict[str, Any]:
    base: dict[str, Any] = {
        "name": "steel",
        "constitutive_law": {"name": "LinearElasticPlaneStrain2DLaw"},
        "Variables": {"YOUNG_MODULUS": 200.0, "POISSON_RATIO": 0.3},
    }
    base.update(material)
    return {"model_part_name": "Structure.Parts_a", "properties_id": 1, "Material": base}


def _write(tmp_path: Path, *blocks: dict[str, Any]) -> str:
    path = tmp_path / "case_materials.json"
    path.write_text(json.dumps({"properties": list(blocks)}, indent=4))
    return str(path)


def test_properties_go_to_the_elements_and_conditions_of_the_part(tmp_path: Path) -> None:
    model = _model()
    ReadMaterials(model, _write(tmp_path, _block()))
    part = model.GetModelPart("Structure")
    assert part.GetElement(1).Properties.Id == 1
    assert part.GetCondition(1).Properties.Id == 1  # conditions of the part too
    assert part.GetElement(2).Properties.Id == 0  # another part keeps its properties
    props = part.GetElement(1).Properties
    assert props[ca.YOUNG_MODULUS] == 200.0
    assert props[ca.CONSTITUTIVE_LAW].Info() == "LinearElasticPlaneStrain2DLaw"
    assert model.GetModelPart("Structure.Parts_a").HasProperties(1)


def test_module_prefixes_are_stripped_and_bare_names_resolve(tmp_path: Path) -> None:
    block = _block(
        constitutive_law={
            "name": "KratosMultiphysics.StructuralMechanicsApplication.HyperElastic3DLaw"
        },
        Variables={
            "KratosMultiphysics.YOUNG_MODULUS": 5.0,
            "KratosMultiphysics.StructuralMechanicsApplication.DENSITY": 2.0,
        },
    )
    block["model_part_name"] = "Parts_b"
    model = _model()
    ReadMaterials(model, _write(tmp_path, block))
    props = model.GetModelPart("Structure").GetElement(2).Properties
    assert props[ca.CONSTITUTIVE_LAW].Info() == "HyperElastic3DLaw"
    assert (props[ca.YOUNG_MODULUS], props[ca.DENSITY]) == (5.0, 2.0)


def test_every_value_kind_and_tables(tmp_path: Path) -> None:
    block = _block(
        Variables={
            "YOUNG_MODULUS": 7,
            "INTEGRATION_ORDER": 3,
            "COMPUTE_LUMPED_MASS_MATRIX": True,
            "TYING_VARIABLE": "DISPLACEMENT",
            "VOLUME_ACCELERATION": [0.0, -9.81, 0.0],
            "INITIAL_STRAIN_VECTOR": [1e-3, 0.0, 0.0],
            "CONSTITUTIVE_MATRIX": [[1.0, 2.0], [3.0, 4.0]],
        },
        Tables={
            "stiffening": {
                "input_variable": "TEMPERATURE",
                "output_variable": "KratosMultiphysics.YOUNG_MODULUS",
                "data": [[0.0, 100.0], [10.0, 200.0]],
            }
        },
    )
    model = _model()
    ReadMaterials(model, _write(tmp_path, block))
    props = model.GetModelPart("Structure").GetElement(1).Properties
    assert props[ca.YOUNG_MODULUS] == 7.0
    assert props[ca.INTEGRATION_ORDER] == 3
    assert props[ca.COMPUTE_LUMPED_MASS_MATRIX] is True
    assert props[ca.TYING_VARIABLE] == "DISPLACEMENT"
    np.testing.assert_allclose(props[ca.VOLUME_ACCELERATION], [0.0, -9.81, 0.0])
    np.testing.assert_allclose(props[ca.INITIAL_STRAIN_VECTOR], [1e-3, 0.0, 0.0])
    np.testing.assert_allclose(props[ca.CONSTITUTIVE_MATRIX], [[1.0, 2.0], [3.0, 4.0]])
    assert props.GetTable(ca.TEMPERATURE, ca.YOUNG_MODULUS).GetValue(5.0) == pytest.approx(150.0)


def test_existing_properties_are_reused_and_overwrites_warned(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    model = _model()
    existing = model.GetModelPart("Structure").CreateNewProperties(1)
    existing[ca.YOUNG_MODULUS] = 1.0
    with caplog.at_level(logging.WARNING, logger="contact_app"):
        ReadMaterials(model, _write(tmp_path, _block()))
    assert model.GetModelPart("Structure").GetElement(1).Properties == existing
    assert existing[ca.YOUNG_MODULUS] == 200.0
    assert "properties 1: YOUNG_MODULUS already set" in caplog.text


def test_two_blocks_on_the_same_entities_warn(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    second = _block()
    second.update(model_part_name="Structure", properties_id=2)
    with caplog.at_level(logging.WARNING, logger="contact_app"):
        ReadMaterials(_model(), _write(tmp_path, _block(), second))
    assert "2 entities of Structure received properties 2" in caplog.text


@pytest.mark.parametrize(
    ("block", "error", "message"),
    [
        (
            _block(constitutive_law={"name": "LinearElasticPlaneStrain2DLow"}),
            ca.InputError,
            'did you mean "LinearElasticPlaneStrain2DLaw"',
        ),
        (_block(Variables={"YOUNGS_MODULUS": 1.0}), ca.InputError, 'did you mean "YOUNG_MODULUS"'),
        (_block(Variables={"YOUNG_MODULUS": "1.0"}), ca.InputError, "wrong type: found a string"),
        (_block(Variables={"YOUNG_MODULUS": True}), ca.InputError, "wrong type: found a bool"),
        (_block(Variables={"INTEGRATION_ORDER": 2.5}), ca.InputError, "an integer"),
        (_block(Variables={"VOLUME_ACCELERATION": [1.0, 2.0]}), ca.InputError, "3 numbers"),
        (
            _block(Variables={"CONSTITUTIVE_MATRIX": [[1.0], [1.0, 2.0]]}),
            ca.InputError,
            "rectangular",
        ),
        (
            _block(Variables={"CONSTITUTIVE_LAW": "x"}),
            ca.InputError,
            "CONSTITUTIVE_LAW is not a value",
        ),
        (
            _block(constitutive_law={"name": "LinearElastic3DLaw", "size": 3}),
            ca.InputError,
            'unknown key "size"',
        ),
        (
            _block(
                Tables={
                    "t": {
                        "input_variable": "TEMPERATURE",
                        "output_variable": "DISPLACEMENT",
                        "data": [[0, 1]],
                    }
                }
            ),
            ca.InputError,
            "not a scalar variable",
        ),
        (
            _block(
                Tables={
                    "t": {
                        "input_variable": "TEMPERATURE",
                        "output_variable": "YOUNG_MODULUS",
                        "data": [[0, 1, 2]],
                    }
                }
            ),
            ca.InputError,
            "rows of two numbers",
        ),
        (_block(Varibles={}), ca.InputError, 'did you mean "Variables"'),
        (
            {"properties_id": 1, "Material": {}},
            ca.InputError,
            'missing required key "model_part_name"',
        ),
        (
            {"model_part_name": "Parts_a", "properties_id": -1},
            ca.InputError,
            '"properties_id" is -1',
        ),
        (
            {
                "model_part_name": "Parts_a",
                "properties_id": 1,
                "sub_properties": [{"properties_id": 2}],
            },
            ca.ConfigurationError,
            "sub_properties",
        ),
    ],
)
def test_invalid_materials_are_rejected_before_any_model(
    tmp_path: Path, block: dict[str, Any], error: type[Exception], message: str
) -> None:
    with pytest.raises(error, match=message) as failure:
        MaterialsReader(_write(tmp_path, block))
    assert "case_materials.json › properties › [0]" in str(failure.value)


def test_unknown_model_part_suggests_a_name(tmp_path: Path) -> None:
    block = _block()
    block["model_part_name"] = "Parts_c"
    reader = MaterialsReader(_write(tmp_path, block))
    with pytest.raises(ca.InputError, match="Parts_c") as failure:
        reader.Apply(_model())
    assert "model_part_name" in str(failure.value)
    assert "did you mean" in str(failure.value)


def test_root_must_be_an_object_with_properties(tmp_path: Path) -> None:
    path = tmp_path / "m.json"
    path.write_text(json.dumps({"propertys": []}))
    with pytest.raises(ca.InputError, match='did you mean "properties"'):
        MaterialsReader(str(path))
    path.write_text("[]")
    with pytest.raises(ca.InputError, match="not a JSON object"):
        MaterialsReader(str(path))


def test_ambiguous_bare_name_is_an_error(tmp_path: Path) -> None:
    model = _model()
    part = model.GetModelPart("Structure")
    part.GetSubModelPart("Parts_a").CreateSubModelPart("skin")
    part.GetSubModelPart("Parts_b").CreateSubModelPart("skin")
    block = _block()
    block["model_part_name"] = "skin"
    with pytest.raises(ca.InputError, match='model part name "skin" is ambiguous'):
        ReadMaterials(model, _write(tmp_path, block))
    block["model_part_name"] = "Structure.Parts_b.skin"
    ReadMaterials(model, _write(tmp_path, block))
    assert part.GetSubModelPart("Parts_b").GetSubModelPart("skin").HasProperties(1)
