"""Model and model parts: hierarchy, lookups, containers, lifetime and errors."""

from __future__ import annotations

import gc

import pytest

import contact_app as ca


def test_model_part_from_temporary_model_stays_valid() -> None:
    model_part = ca.Model().CreateModelPart("X")
    gc.collect()
    model_part.CreateNewNode(1, 0.0, 0.0, 0.0)
    assert model_part.NumberOfNodes() == 1
    assert model_part.GetModel().GetModelPartNames() == ["X"]
    sub = ca.Model().CreateModelPart("Y").CreateSubModelPart("Z")
    gc.collect()
    assert sub.FullName() == "Y.Z" and sub.GetRootModelPart().Name == "Y"


def test_model_part_containers_keep_their_model_part_alive() -> None:
    model_part = ca.Model().CreateModelPart("X")
    model_part.CreateNewNode(1, 0.0, 0.0, 0.0)
    nodes = model_part.Nodes
    iterator = iter(model_part.Nodes)
    del model_part
    gc.collect()
    assert len(nodes) == 1
    assert next(iterator).Id == 1


def test_model_dotted_lookups(model: ca.Model) -> None:
    main = model.CreateModelPart("Main")
    main.CreateSubModelPart("A").CreateSubModelPart("B")
    deep = model.GetModelPart("Main.A.B")
    assert deep.FullName() == "Main.A.B" and deep.Name == "B"
    assert model["Main.A"].GetSubModelPart("B") == deep
    assert main.GetSubModelPart("A.B") == deep
    assert deep.GetParentModelPart() == model["Main.A"] and deep.GetRootModelPart() == main
    assert deep.IsSubModelPart() and not main.IsSubModelPart()
    assert model.HasModelPart("Main.A.B") and "Main.A" in model and not model.HasModelPart("Main.C")
    assert main.HasSubModelPart("A") and main.GetSubModelPartNames() == ["A"]
    assert [part.Name for part in main.SubModelParts] == ["A"]


def test_model_unknown_model_part_lists_existing_ones(model: ca.Model) -> None:
    model.CreateModelPart("Main").CreateSubModelPart("Contact")
    with pytest.raises(
        ca.InputError, match='(?s)no sub model part "Contac".*did you mean "Contact"'
    ):
        model.GetModelPart("Main.Contac")


def test_model_create_delete_and_names(model: ca.Model) -> None:
    model.CreateModelPart("B")
    model.CreateModelPart("A", 3)
    assert model.GetModelPartNames() == ["A", "B"]
    assert model["A"].GetBufferSize() == 3
    with pytest.raises(ca.InputError):
        model.CreateModelPart("A")
    model.DeleteModelPart("B")
    assert model.GetModelPartNames() == ["A"]


def test_sub_model_part_membership_propagates_to_parents(structure: ca.ModelPart) -> None:
    contact = structure.CreateSubModelPart("Contact")
    slave = contact.CreateSubModelPart("Slave")
    slave.CreateNewNode(5, 1.0, 2.0, 0.0)
    properties = slave.CreateNewProperties(2)
    slave.CreateNewNode(6, 2.0, 2.0, 0.0)
    slave.CreateNewCondition("LineCondition2D2N", 1, [5, 6], properties)
    for part in (slave, contact, structure):
        assert part.HasNode(5) and part.NumberOfNodes() == 2
        assert part.HasCondition(1) and part.NumberOfConditions() == 1
        assert part.HasProperties(2)
    structure.CreateNewNode(7, 0.0, 0.0, 0.0)
    assert structure.NumberOfNodes() == 3 and contact.NumberOfNodes() == 2
    # The historical layout is the root's.
    assert slave.GetNode(5).SolutionStepsDataHas(ca.DISPLACEMENT)


def test_model_part_add_nodes_by_id(rectangle: ca.ModelPart) -> None:
    top = rectangle.CreateSubModelPart("Top")
    top.AddNodes([4, 5, 6])
    top.AddNode(rectangle.GetNode(1))
    assert [node.Id for node in top.Nodes] == [1, 4, 5, 6]
    with pytest.raises(ca.InputError, match="99"):
        top.AddNodes([99])


def test_model_part_remove_node_from_sub_model_parts(rectangle: ca.ModelPart) -> None:
    top = rectangle.CreateSubModelPart("Top")
    top.AddNodes([4, 5])
    rectangle.RemoveNode(4)
    assert not rectangle.HasNode(4) and not top.HasNode(4) and top.NumberOfNodes() == 1
    top.RemoveNode(5)
    assert rectangle.HasNode(5) and not top.HasNode(5)


def test_model_part_duplicate_node_id_raises(rectangle: ca.ModelPart) -> None:
    with pytest.raises(ca.InputError, match="node id 3 is already used in model part Structure"):
        rectangle.CreateNewNode(3, 9.0, 9.0, 9.0)
    with pytest.raises(ca.InputError, match="node id 3 is already used"):
        rectangle.CreateSubModelPart("Sub").CreateNewNode(3, 9.0, 9.0, 9.0)


def test_model_part_missing_node_raises(rectangle: ca.ModelPart) -> None:
    with pytest.raises(ca.InputError, match="42"):
        rectangle.GetNode(42)


def test_model_part_unknown_element_name_suggests_close_name(rectangle: ca.ModelPart) -> None:
    properties = rectangle.GetProperties(1)
    with pytest.raises(
        ca.InputError, match='(?s)unknown element "Element2D4M".*did you mean "Element2D4N"'
    ):
        rectangle.CreateNewElement("Element2D4M", 1, [1, 2, 5, 4], properties)
    with pytest.raises(ca.InputError, match="unknown condition"):
        rectangle.CreateNewCondition("LineCondition2D2M", 1, [1, 2], properties)


def test_model_part_containers_iterate_in_id_order(structure: ca.ModelPart) -> None:
    for node_id in (3, 1, 2):
        structure.CreateNewNode(node_id, float(node_id), 0.0, 0.0)
    properties = structure.CreateNewProperties(1)
    for element_id, nodes in ((2, [2, 3]), (1, [1, 2])):
        structure.CreateNewElement("Element2D2N", element_id, nodes, properties)
    assert [node.Id for node in structure.Nodes] == [1, 2, 3]
    assert [element.Id for element in structure.Elements] == [1, 2]
    assert (
        len(structure.Nodes) == 3
        and len(structure.Elements) == 2
        and len(structure.Conditions) == 0
    )
    assert 2 in structure.Nodes and 4 not in structure.Nodes
    assert structure.GetNode(2) in structure.Nodes
    assert structure.GetElement(2) in structure.Elements
    assert not structure.Conditions and len(structure.MasterSlaveConstraints) == 0


def test_model_part_elements_and_conditions(rectangle: ca.ModelPart) -> None:
    properties = rectangle.GetProperties(1)
    rectangle.CreateNewElement("Element2D4N", 1, [1, 2, 5, 4], properties)
    rectangle.CreateNewElement("Element2D4N", 2, [2, 3, 6, 5], properties)
    rectangle.CreateNewCondition("LineCondition2D2N", 1, [1, 2], properties)
    boundary = rectangle.CreateSubModelPart("Boundary")
    boundary.AddConditions([1])
    boundary.AddElements([2])
    assert rectangle.NumberOfElements() == 2 and rectangle.NumberOfConditions() == 1
    assert boundary.GetElement(2).Id == 2 and boundary.NumberOfElements() == 1
    assert boundary.GetCondition(1) == rectangle.GetCondition(1)
    rectangle.RemoveElement(2)
    assert not boundary.HasElement(2) and rectangle.NumberOfElements() == 1
    with pytest.raises(ca.InputError, match="element id 1 is already used"):
        rectangle.CreateNewElement("Element2D4N", 1, [1, 2, 5, 4], properties)


def test_model_part_remove_conditions_flagged(rectangle: ca.ModelPart) -> None:
    properties = rectangle.GetProperties(1)
    for condition_id, nodes in ((1, [1, 2]), (2, [2, 3])):
        rectangle.CreateNewCondition("LineCondition2D2N", condition_id, nodes, properties)
    rectangle.GetCondition(2).Set(ca.TO_ERASE)
    assert rectangle.RemoveConditionsFlagged(ca.TO_ERASE) == 1
    assert [condition.Id for condition in rectangle.Conditions] == [1]


def test_model_part_master_slave_constraint(rectangle: ca.ModelPart) -> None:
    master, slave = rectangle.GetNode(1), rectangle.GetNode(2)
    for node in (master, slave):
        node.AddDof(ca.DISPLACEMENT_X, ca.REACTION_X)
    constraint = rectangle.CreateNewMasterSlaveConstraint(
        "LinearMasterSlaveConstraint",
        1,
        master,
        ca.DISPLACEMENT_X,
        slave,
        ca.DISPLACEMENT_X,
        2.0,
        0.5,
    )
    assert rectangle.NumberOfMasterSlaveConstraints() == 1
    assert rectangle.GetMasterSlaveConstraint(1) == constraint
    relation, constant = constraint.CalculateLocalSystem(rectangle.ProcessInfo)
    assert relation.tolist() == [[2.0]] and constant.tolist() == [0.5]
    slaves, masters = constraint.GetDofList(rectangle.ProcessInfo)
    assert [dof.Id() for dof in slaves] == [2] and [dof.Id() for dof in masters] == [1]
    master.SetSolutionStepValue(ca.DISPLACEMENT_X, 0, 1.0)
    constraint.Apply(rectangle.ProcessInfo)
    assert slave.GetSolutionStepValue(ca.DISPLACEMENT_X) == pytest.approx(2.5)
    dofs = [slave.GetDof(ca.DISPLACEMENT_X)], [master.GetDof(ca.DISPLACEMENT_X)]
    rectangle.CreateNewMasterSlaveConstraint(
        "LinearMasterSlaveConstraint", 2, dofs[1], dofs[0], [[1.0]], [0.0]
    )
    assert [c.Id for c in rectangle.MasterSlaveConstraints] == [1, 2]


def test_model_part_data_values_and_flags(structure: ca.ModelPart) -> None:
    structure.SetValue(ca.DOMAIN_SIZE, 2)
    structure.Set(ca.CONTACT)
    assert structure.GetValue(ca.DOMAIN_SIZE) == 2 and structure.Has(ca.DOMAIN_SIZE)
    assert structure.Is(ca.CONTACT)


def test_model_part_info_lists_counts_and_tree(rectangle: ca.ModelPart) -> None:
    rectangle.CreateSubModelPart("Contact")
    text = str(rectangle)
    assert text == rectangle.Info()
    assert "ModelPart Structure: 6 nodes, 0 elements" in text
    assert "  ModelPart Structure.Contact: 0 nodes" in text
    assert repr(rectangle) == "<ModelPart Structure>"


def test_model_part_historical_variables_and_buffer(structure: ca.ModelPart) -> None:
    assert structure.HasNodalSolutionStepVariable(ca.DISPLACEMENT)
    assert not structure.HasNodalSolutionStepVariable(ca.VELOCITY)
    node = structure.CreateNewNode(1, 0.0, 0.0, 0.0)
    structure.AddNodalSolutionStepVariable(ca.VELOCITY)
    node.SetSolutionStepValue(ca.VELOCITY_X, 0, 3.0)
    assert node.GetSolutionStepValue(ca.VELOCITY_X) == 3.0
    structure.SetBufferSize(3)
    assert structure.GetBufferSize() == 3 and node.GetBufferSize() == 3


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), -float("inf")])
def test_model_part_refuses_non_finite_coordinates_and_times(
    structure: ca.ModelPart, bad: float
) -> None:
    with pytest.raises(ca.InputError, match="node 91 of model part .* has a non-finite coordinate"):
        structure.CreateNewNode(91, 0.0, 0.0, bad)
    assert not structure.HasNode(91)
    with pytest.raises(ca.InputError, match="the new time is not finite"):
        structure.CloneTimeStep(bad)
    node = structure.CreateNewNode(92, 0.0, 0.0, 0.0)
    for name in ("X", "Y", "Z", "X0", "Y0", "Z0"):
        with pytest.raises(ca.InputError, match=f"coordinate {name.lower()} of node 92 set to"):
            setattr(node, name, bad)
    with pytest.raises(ca.InputError, match="coordinates of node 92 set to"):
        node.SetCoordinates([0.0, bad, 0.0])
    with pytest.raises(ca.InputError, match="initial coordinates of node 92"):
        node.SetInitialCoordinates([bad, 0.0, 0.0])
    with pytest.raises(ca.InputError, match="coordinate y of node 7"):
        ca.Node(7, 0.0, bad, 0.0)
    assert list(node.Coordinates()) == [0.0, 0.0, 0.0]


def test_model_part_refuses_ids_beyond_what_outputs_store(structure: ca.ModelPart) -> None:
    with pytest.raises(ca.InputError, match="beyond the largest id 9223372036854775807"):
        structure.CreateNewNode(2**63, 0.0, 0.0, 0.0)
