"""vtk_output_process: .vtu files readable by meshio with the requested data, .pvd, scheduling."""

from __future__ import annotations

import logging
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import meshio
import numpy as np
import pytest
from conftest import build_plate, create, impose_displacement
from contact.patch_meshes import HEX_CORNERS  # tests/python/contact/patch_meshes.py

import contact_app as ca


def _vtk(model: ca.Model, tmp_path: Path, **settings: Any) -> Any:
    parameters = {"model_part_name": "Structure", "output_path": str(tmp_path / "vtk"), **settings}
    return create("vtk_output_process", parameters, model)


def _run(plate: ca.ModelPart, process: Any, times: list[float]) -> list[float]:
    """Drive the output part of the life cycle; return the times at which output was written."""
    process.ExecuteInitialize()
    process.ExecuteBeforeSolutionLoop()
    written = []
    for time in times:
        plate.CloneTimeStep(time)
        impose_displacement(plate, time)
        if process.IsOutputStep():
            process.PrintOutput()
            written.append(time)
    return written


def _pvd(path: Path) -> list[tuple[float, str]]:
    root = ET.parse(path).getroot()
    assert root.attrib["type"] == "Collection"
    return [(float(d.attrib["timestep"]), d.attrib["file"]) for d in root.iter("DataSet")]


@pytest.mark.parametrize("file_format", ["binary", "ascii"])
def test_vtk_files_carry_points_cells_and_requested_data(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path, file_format: str
) -> None:
    process = _vtk(
        model,
        tmp_path,
        file_format=file_format,
        write_ids=True,
        nodal_solution_step_data_variables=["DISPLACEMENT", "REACTION_X"],
        nodal_data_value_variables=["AUGMENTED_NORMAL_CONTACT_PRESSURE"],
        nodal_flags=["ACTIVE"],
        element_data_value_variables=["NODAL_AREA"],
        element_flags=["ACTIVE"],
        gauss_point_variables_in_elements=["VON_MISES_STRESS", "CAUCHY_STRESS_VECTOR"],
        gauss_point_variables_extrapolated_to_nodes=["CAUCHY_STRESS_VECTOR"],
    )
    plate.GetNode(5).SetValue(ca.AUGMENTED_NORMAL_CONTACT_PRESSURE, -3.5)
    plate.GetNode(5).Set(ca.ACTIVE, True)
    plate.GetElement(4).SetValue(ca.NODAL_AREA, 0.25)
    plate.GetElement(2).Set(ca.ACTIVE, True)
    assert _run(plate, process, [0.5, 1.0]) == [0.5, 1.0]
    mesh = meshio.read(tmp_path / "vtk" / "Structure_0_2.vtu")
    np.testing.assert_allclose(mesh.points[:, :2], [[n.X0, n.Y0] for n in plate.Nodes])
    assert [(block.type, len(block.data)) for block in mesh.cells] == [("quad", 4)]
    np.testing.assert_array_equal(mesh.cells[0].data[3], [4, 5, 8, 7])  # element 4, 0-based
    rtol = 1e-6 if file_format == "ascii" else 1e-14
    expected = [[0.01 * n.X0, -0.02 * n.Y0, 0.0] for n in plate.Nodes]
    np.testing.assert_allclose(mesh.point_data["DISPLACEMENT"], expected, rtol=rtol, atol=1e-20)
    assert mesh.point_data["REACTION_X"].shape == (9,)
    assert mesh.point_data["AUGMENTED_NORMAL_CONTACT_PRESSURE"][4] == -3.5
    np.testing.assert_array_equal(mesh.point_data["ACTIVE"], [0, 0, 0, 0, 1, 0, 0, 0, 0])
    np.testing.assert_array_equal(mesh.point_data["KRATOS_NODE_ID"], range(1, 10))
    np.testing.assert_array_equal(mesh.cell_data["KRATOS_ELEMENT_ID"][0], [1, 2, 3, 4])
    np.testing.assert_array_equal(mesh.cell_data["NODAL_AREA"][0], [0, 0, 0, 0.25])
    np.testing.assert_array_equal(mesh.cell_data["ACTIVE"][0], [0, 1, 0, 0])
    info = plate.ProcessInfo
    for element, mises in zip(plate.Elements, mesh.cell_data["VON_MISES_STRESS"][0], strict=True):
        gauss = element.CalculateOnIntegrationPoints(ca.VON_MISES_STRESS, info)
        assert mises == pytest.approx(np.mean(gauss), rel=rtol)
    # uniform strain: every integration point has the same stress, so do the extrapolated nodes
    stress = plate.GetElement(1).CalculateOnIntegrationPoints(ca.CAUCHY_STRESS_VECTOR, info)[0]
    np.testing.assert_allclose(
        mesh.point_data["CAUCHY_STRESS_VECTOR"], np.tile(stress, (9, 1)), rtol=rtol, atol=1e-12
    )
    assert mesh.cell_data["CAUCHY_STRESS_VECTOR"][0].shape == (4, 3)
    assert _pvd(tmp_path / "vtk" / "Structure.pvd") == [
        (0.5, "Structure_0_1.vtu"),
        (1.0, "Structure_0_2.vtu"),
    ]


def test_vtk_extrapolation_to_nodes_is_exact_for_bilinear_fields(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path
) -> None:
    process = _vtk(
        model, tmp_path, gauss_point_variables_extrapolated_to_nodes=["CAUCHY_STRESS_VECTOR"]
    )
    plate.CloneTimeStep(1.0)
    for node in plate.Nodes:  # u = (0.01 x y, 0): eps_xx = 0.01 y, gamma_xy = 0.01 x
        node.SetSolutionStepValue(ca.DISPLACEMENT, 0, [0.01 * node.X0 * node.Y0, 0.0, 0.0])
    process.PrintOutput()
    stress = meshio.read(tmp_path / "vtk" / "Structure_0_1.vtu").point_data["CAUCHY_STRESS_VECTOR"]
    young, poisson = 200.0, 0.3  # plane stress
    for i, node in enumerate(plate.Nodes):
        expected = young / (1 - poisson**2) * 0.01 * node.Y0 * np.array([1.0, poisson, 0.0])
        expected[2] = young / (2 * (1 + poisson)) * 0.01 * node.X0
        np.testing.assert_allclose(stress[i], expected, rtol=1e-12, atol=1e-12)


def test_vtk_conditions_submodel_parts_deformed_and_naming(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path
) -> None:
    process = _vtk(
        model,
        tmp_path,
        model_part_name="Structure.Top",
        entity_type="condition",
        write_deformed_configuration=True,
        custom_name_prefix="pre_",
        custom_name_postfix="_post",
        condition_data_value_variables=["LINE_LOAD"],
        condition_flags=["SLAVE"],
    )
    plate.GetCondition(1).SetValue(ca.LINE_LOAD, [0.0, -2.0, 0.0])
    plate.CloneTimeStep(1.0)
    impose_displacement(plate, 1.0)
    ca.VariableUtils().UpdateCurrentPosition(plate.Nodes)
    process.PrintOutput()
    folder = tmp_path / "vtk"
    assert sorted(p.name for p in folder.iterdir()) == [
        "pre_Structure_Top_0_1_post.vtu",
        "pre_Structure_Top_post.pvd",
    ]
    mesh = meshio.read(folder / "pre_Structure_Top_0_1_post.vtu")
    assert [(block.type, len(block.data)) for block in mesh.cells] == [("line", 2)]
    np.testing.assert_allclose(mesh.points[:, 0], [0.0, 1.01, 2.02])  # deformed: x + 0.01 x
    np.testing.assert_allclose(mesh.cell_data["LINE_LOAD"][0], [[0, -2, 0], [0, 0, 0]])
    np.testing.assert_array_equal(mesh.cell_data["SLAVE"][0], [0, 0])


def test_vtk_sub_model_parts_and_nodes_only_parts(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path
) -> None:
    process = _vtk(
        model,
        tmp_path,
        output_sub_model_parts=True,
        nodal_solution_step_data_variables=["DISPLACEMENT"],
    )
    _run(plate, process, [1.0])
    folder = tmp_path / "vtk"
    names = sorted(p.name for p in folder.glob("*.vtu"))
    assert names == [
        "Structure_0_1.vtu",
        "Structure_Body_0_1.vtu",
        "Structure_Bottom_0_1.vtu",
        "Structure_Top_0_1.vtu",
    ]
    bottom = meshio.read(folder / "Structure_Bottom_0_1.vtu")  # nodes only: vertex cells
    assert [(block.type, len(block.data)) for block in bottom.cells] == [("vertex", 3)]
    top = meshio.read(folder / "Structure_Top_0_1.vtu")  # automatic: no elements -> conditions
    assert top.cells[0].type == "line"
    np.testing.assert_allclose(top.point_data["DISPLACEMENT"][:, 1], [-0.04] * 3)


def test_vtk_step_interval_and_time_control(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path
) -> None:
    by_step = _vtk(model, tmp_path, output_interval=2)
    # next output starts at STEP 0: steps 1, then 2, 4, 6 (Kratos' schedule)
    written = _run(plate, by_step, [0.1 * k for k in range(1, 7)])
    assert written == pytest.approx([0.1, 0.2, 0.4, 0.6])
    second = ca.Model()
    other = build_plate(second)
    by_time = create(
        "vtk_output_process",
        {
            "model_part_name": "Structure",
            "output_control_type": "time",
            "output_interval": 0.25,
            "output_path": str(tmp_path / "timed"),
        },
        second,
    )
    written = _run(other, by_time, [0.1 * k for k in range(1, 11)])
    assert written == pytest.approx([0.1, 0.3, 0.5, 0.8, 1.0])
    assert [t for t, _ in _pvd(tmp_path / "timed" / "Structure.pvd")] == pytest.approx(written)


def test_vtk_every_step_with_zero_interval(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path
) -> None:
    process = _vtk(model, tmp_path, output_interval=0.0)
    assert _run(plate, process, [1.0, 2.0, 3.0]) == [1.0, 2.0, 3.0]


def test_vtk_initialize_removes_only_old_files_of_its_pattern(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path
) -> None:
    folder = tmp_path / "vtk"
    folder.mkdir()
    for name in ("Structure_0_7.vtu", "Structure.pvd", "Structure_Top_0_1.vtu", "notes.txt"):
        (folder / name).write_text("old")
    process = _vtk(model, tmp_path)
    process.ExecuteInitialize()
    assert sorted(p.name for p in folder.iterdir()) == ["Structure_Top_0_1.vtu", "notes.txt"]


def test_vtk_legacy_keys_of_the_kratos_cases_are_converted(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    with caplog.at_level(logging.WARNING):
        process = create(
            "vtk_output_process",
            {
                "model_part_name": "Structure",
                "output_control_type": "step",
                "output_frequency": 1,
                "file_format": "ascii",
                "output_precision": 7,
                "output_sub_model_parts": False,
                "folder_name": str(tmp_path / "vtk_output"),
                "save_output_files_in_folder": True,
                "nodal_solution_step_data_variables": ["DISPLACEMENT"],
                "nodal_data_value_variables": [],
                "nodal_flags": ["ACTIVE", "MASTER", "SLAVE"],
                "element_data_value_variables": [],
                "element_flags": [],
                "condition_data_value_variables": [],
                "condition_flags": [],
                "gauss_point_variables_extrapolated_to_nodes": [],
            },
            model,
        )
    assert '"output_frequency" is the old name of "output_interval"' in caplog.text
    assert '"folder_name" is the old name of "output_path"' in caplog.text
    _run(plate, process, [1.0])
    assert (tmp_path / "vtk_output" / "Structure_0_1.vtu").exists()


def test_vtk_ascii_precision_rounds_values(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path
) -> None:
    process = _vtk(
        model,
        tmp_path,
        file_format="ascii",
        output_precision=3,
        nodal_data_value_variables=["NODAL_AREA"],
    )
    plate.GetNode(1).SetValue(ca.NODAL_AREA, 1.23456789)
    process.PrintOutput()
    mesh = meshio.read(tmp_path / "vtk" / "Structure_0_0.vtu")
    assert mesh.point_data["NODAL_AREA"][0] == 1.23


@pytest.mark.parametrize(
    ("settings", "message"),
    [
        ({"file_format": "xml"}, 'expected: "binary" or "ascii"'),
        ({"output_control_type": "steps"}, 'expected: "step" or "time"'),
        ({"entity_type": "elements"}, '"automatic" or "element" or "condition"'),
        ({"output_frequency": 1, "output_interval": 1.0}, 'both "output_frequency"'),
        (
            {"nodal_solution_step_data_variables": ["AUGMENTED_NORMAL_CONTACT_PRESSURE"]},
            "not a historical",
        ),
        ({"nodal_flags": ["ACTIV"]}, 'did you mean "ACTIVE"'),
        (
            {
                "nodal_data_value_variables": ["NODAL_AREA"],
                "nodal_solution_step_data_variables": ["DISPLACEMENT"],
                "gauss_point_variables_extrapolated_to_nodes": ["NODAL_AREA"],
            },
            "requested twice",
        ),
        ({"write_vtm": True}, 'unknown key "write_vtm"'),
    ],
)
def test_vtk_bad_settings_raise_input_error(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path, settings: dict[str, Any], message: str
) -> None:
    with pytest.raises(ca.InputError, match=message):
        _vtk(model, tmp_path, **settings)


def test_vtk_mixed_cell_types_in_2d_and_3d(tmp_path: Path) -> None:
    model = ca.Model()
    mp = model.CreateModelPart("Mixed")
    mp.AddNodalSolutionStepVariable(ca.DISPLACEMENT)
    props = mp.CreateNewProperties(0)
    coordinates = [
        *HEX_CORNERS,  # nodes 1-8: the unit cube, in the hexahedron's corner order
        (2, 0, 0),
        (2, 1, 0),
        (2, 0, 1),
        (0.5, 0, 0),
        (0.5, 0.5, 0),
        (0, 0.5, 0),
        (0, 0, 0.5),
        (0.5, 0, 0.5),
        (0, 0.5, 0.5),
        (3, 0, 0),
    ]
    for node_id, xyz in enumerate(coordinates, 1):
        mp.CreateNewNode(node_id, *xyz)
    elements = [
        ("Element3D8N", [1, 2, 3, 4, 5, 6, 7, 8]),
        ("Element3D6N", [2, 9, 3, 6, 11, 7]),
        ("Element3D4N", [9, 10, 3, 11]),
        ("Element3D10N", [1, 2, 4, 5, 12, 13, 14, 15, 16, 17]),
        ("Element3D4N", [9, 18, 10, 11]),
    ]
    for element_id, (name, nodes) in enumerate(elements, 1):
        mp.CreateNewElement(name, element_id, nodes, props).SetValue(ca.NODAL_AREA, element_id)
    process = create(
        "vtk_output_process",
        {
            "model_part_name": "Mixed",
            "output_path": str(tmp_path),
            "file_format": "ascii",
            "element_data_value_variables": ["NODAL_AREA"],
        },
        model,
    )
    process.PrintOutput()
    mesh = meshio.read(tmp_path / "Mixed_0_0.vtu")
    assert [(b.type, len(b.data)) for b in mesh.cells] == [
        ("hexahedron", 1),
        ("wedge", 1),
        ("tetra", 2),
        ("tetra10", 1),
    ]
    assert [list(a) for a in mesh.cell_data["NODAL_AREA"]] == [[1.0], [2.0], [3.0, 5.0], [4.0]]
    np.testing.assert_array_equal(mesh.cells[3].data[0], np.array(elements[3][1]) - 1)


def _same_files_both_paths(process: Any, tmp_path: Path) -> None:
    """The bulk arrays and the per-entity path write byte-identical files for every part."""
    for part in process.parts:
        process._write(part, tmp_path / "bulk.vtu")
        process._gather_bulk = process._gather_per_entity
        process._write(part, tmp_path / "per_entity.vtu")
        del process._gather_bulk
        assert (tmp_path / "bulk.vtu").read_bytes() == (tmp_path / "per_entity.vtu").read_bytes()


@pytest.mark.parametrize("file_format", ["binary", "ascii"])
def test_vtk_bulk_arrays_write_the_same_bytes_as_the_per_entity_path(
    model: ca.Model, plate: ca.ModelPart, tmp_path: Path, file_format: str
) -> None:
    plate.CloneTimeStep(1.0)
    impose_displacement(plate, 1.0)
    plate.GetNode(5).SetValue(ca.AUGMENTED_NORMAL_CONTACT_PRESSURE, -3.5)
    plate.GetNode(5).SetValue(ca.NORMAL, [0.0, 1.0, 0.0])
    plate.GetNode(2).Set(ca.ACTIVE, True)
    plate.GetElement(4).SetValue(ca.NODAL_AREA, 0.25)
    plate.GetElement(2).Set(ca.ACTIVE, True)
    plate.GetCondition(1).SetValue(ca.LINE_LOAD, [0.0, -2.0, 0.0])
    elements = _vtk(
        model,
        tmp_path,
        file_format=file_format,
        write_ids=True,
        write_deformed_configuration=True,
        nodal_solution_step_data_variables=["DISPLACEMENT", "REACTION_X"],
        nodal_data_value_variables=["AUGMENTED_NORMAL_CONTACT_PRESSURE", "NORMAL"],
        nodal_flags=["ACTIVE"],
        element_data_value_variables=["NODAL_AREA"],
        element_flags=["ACTIVE"],
        gauss_point_variables_in_elements=["VON_MISES_STRESS", "CAUCHY_STRESS_VECTOR"],
    )
    _same_files_both_paths(elements, tmp_path)
    conditions = _vtk(  # the cells' nodes outside the part are appended
        model,
        tmp_path,
        model_part_name="Structure.Top",
        entity_type="condition",
        write_ids=True,
        file_format=file_format,
        nodal_solution_step_data_variables=["DISPLACEMENT"],
        condition_data_value_variables=["LINE_LOAD"],
        condition_flags=["SLAVE"],
    )
    _same_files_both_paths(conditions, tmp_path)
    parts = _vtk(  # nodes-only parts become vertex cells
        model,
        tmp_path,
        output_sub_model_parts=True,
        write_ids=True,
        file_format=file_format,
        nodal_solution_step_data_variables=["DISPLACEMENT"],
        nodal_flags=["ACTIVE"],
    )
    _same_files_both_paths(parts, tmp_path)


def test_vtk_bulk_entity_values_rows_and_integration_point_means() -> None:
    from contact_app.processes.vtk_output_process import _integration_point_means, _rows

    values = np.array([[1.0, 2.0], [3.0, 0.0]])
    np.testing.assert_array_equal(_rows(values, np.array([1, 1])), [1.0, 3.0])
    np.testing.assert_array_equal(_rows(values, np.array([2, 1])), values)
    assert _rows(np.zeros((0, 0)), np.zeros(0, dtype=np.int64)).shape == (0,)
    rng = np.random.default_rng(5)
    points = [rng.standard_normal((k, 3)) for k in (4, 9, 9, 0, 4)]
    flat = np.zeros((5, 27))
    for e, p in enumerate(points):
        flat[e, : p.size] = p.ravel()
    means, widths = _integration_point_means(
        flat, np.array([p.size for p in points]), np.array([len(p) for p in points])
    )
    for e, p in enumerate(points):  # the per-entity mean, bit for bit
        expected = np.mean(p, axis=0) if len(p) else np.zeros(1)
        assert means[e, : widths[e]].tolist() == expected.tolist()
