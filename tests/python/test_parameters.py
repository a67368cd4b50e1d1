"""Parameters: typed access, write-through setters, defaults and validation messages."""

import pytest

import contact_app as ca
from contact_app.model_part_lookup import get_model_part
from contact_app.parameters import Parameters


def test_parameters_typed_getters_and_write_through() -> None:
    p = Parameters('{"a": {"b": 2, "c": "x", "v": [1, 2.5], "m": [[1, 0], [0, 1]]}}', "case.json")
    assert p["a"]["b"].GetInt() == 2
    assert p["a"]["b"].GetDouble() == 2.0
    assert p["a"]["v"].GetVector() == [1.0, 2.5]
    assert p["a"]["m"].GetMatrix() == [[1.0, 0.0], [0.0, 1.0]]
    p["a"]["c"].SetString("y")
    p["a"]["v"][1].SetDouble(4.0)
    assert p["a"]["c"].GetString() == "y"
    assert p["a"]["v"].GetVector() == [1.0, 4.0]
    assert [k for k, _ in p["a"].items()] == ["b", "c", "v", "m"]


def test_parameters_wrong_type_names_the_path_and_value() -> None:
    p = Parameters('{"solver_settings": {"max_iteration": "ten"}}', "ProjectParameters.json")
    with pytest.raises(ca.InputError) as error:
        p["solver_settings"]["max_iteration"].GetInt()
    message = str(error.value)
    assert "ProjectParameters.json › solver_settings › max_iteration" in message
    assert "found a string ('ten')" in message
    assert "expected: an integer" in message


def test_parameters_validation_suggests_the_misspelt_key() -> None:
    p = Parameters('{"max_iterations": 3}', "case.json")
    with pytest.raises(ca.InputError, match='did you mean "max_iteration"') as error:
        p.ValidateAndAssignDefaults({"max_iteration": 10, "echo_level": 0})
    assert "case.json › max_iterations" in str(error.value)


def test_parameters_validation_adds_defaults_and_accepts_int_for_double() -> None:
    p = Parameters('{"tolerance": 1}')
    p.ValidateAndAssignDefaults({"tolerance": 1.0e-6, "nested": {"x": 1}})
    assert p["tolerance"].GetDouble() == 1.0
    assert p["nested"]["x"].GetInt() == 1
    with pytest.raises(ca.InputError, match='"tolerance" has the wrong type'):
        Parameters('{"tolerance": "small"}').ValidateAndAssignDefaults({"tolerance": 1.0})


def test_parameters_recursive_validation_reaches_nested_blocks() -> None:
    p = Parameters('{"linear_solver_settings": {"solver_typ": "cg"}}', "case.json")
    with pytest.raises(ca.InputError, match="case.json › linear_solver_settings › solver_typ"):
        p.RecursivelyValidateAndAssignDefaults({"linear_solver_settings": {"solver_type": ""}})


def test_parameters_malformed_json_reports_line_and_column() -> None:
    with pytest.raises(ca.InputError, match="line 2, column"):
        Parameters('{"a": 1,\n "b" 2}', "bad.json")


def test_parameters_missing_key_and_missing_file() -> None:
    with pytest.raises(ca.InputError, match='missing key "echo"'):
        Parameters('{"echo_level": 1}')["echo"]
    with pytest.raises(ca.InputError, match="cannot read the settings file"):
        Parameters.from_file("/nonexistent/ProjectParameters.json")


def test_model_part_lookup_accepts_paths_and_bare_names() -> None:
    model = ca.Model()
    structure = model.CreateModelPart("Structure")
    structure.CreateSubModelPart("Parts").CreateSubModelPart("Contact_Part")
    structure.CreateSubModelPart("Other").CreateSubModelPart("Skin")
    structure.GetSubModelPart("Parts").CreateSubModelPart("Skin")
    assert get_model_part(model, "Structure.Parts.Contact_Part").Name == "Contact_Part"
    assert get_model_part(model, "Contact_Part").FullName() == "Structure.Parts.Contact_Part"
    with pytest.raises(ca.InputError, match="ambiguous"):
        get_model_part(model, "Skin")
    with pytest.raises(ca.InputError, match='did you mean "Contact_Part"'):
        get_model_part(model, "Contact_Prt", "case.json › processes")
