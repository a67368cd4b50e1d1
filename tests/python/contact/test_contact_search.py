"""Contact search from Python: two blocks, their pairs, pair conditions, settings validation."""

import pytest

import contact_app as ca


def _two_blocks(n_lower: int, n_upper: int, gap: float) -> ca.ModelPart:
    """Two 1 x 0.5 blocks of quads: the lower top (slave) faces the upper bottom (master)."""
    model = ca.Model()
    main = model.CreateModelPart("Structure")
    for variable in (
        ca.DISPLACEMENT,
        ca.NORMAL,
        ca.NODAL_H,
        ca.WEIGHTED_GAP,
        ca.LAGRANGE_MULTIPLIER_CONTACT_PRESSURE,
    ):
        main.AddNodalSolutionStepVariable(variable)
    props = main.CreateNewProperties(1)
    contact = main.CreateSubModelPart("Contact")
    utils = ca.VariableUtils()
    next_node = [1]

    def block(nx: int, y0: float, first_element: int) -> list[list[int]]:
        ids = []
        for j in range(3):
            row = []
            for i in range(nx + 1):
                node = main.CreateNewNode(next_node[0], i / nx, y0 + 0.25 * j, 0.0)
                node.SetSolutionStepValue(ca.NODAL_H, 0, 1.0 / nx)
                for dof in (
                    ca.DISPLACEMENT_X,
                    ca.DISPLACEMENT_Y,
                    ca.LAGRANGE_MULTIPLIER_CONTACT_PRESSURE,
                ):
                    node.AddDof(dof)
                row.append(next_node[0])
                next_node[0] += 1
            ids.append(row)
        for j in range(2):
            for i in range(nx):
                quad = [ids[j][i], ids[j][i + 1], ids[j + 1][i + 1], ids[j + 1][i]]
                main.CreateNewElement("Element2D4N", first_element + j * nx + i, quad, props)
        return ids

    lower = block(n_lower, -0.5, 1)
    upper = block(n_upper, gap, 1000)
    # Outward normals: lower top edge right-to-left (+y), upper bottom edge left-to-right (-y).
    slave_ids, master_ids = [], []
    for i in range(n_lower):
        c = main.CreateNewCondition(
            "LineCondition2D2N", 1 + i, [lower[2][i + 1], lower[2][i]], props
        )
        slave_ids.append(c.Id)
    for i in range(n_upper):
        c = main.CreateNewCondition(
            "LineCondition2D2N", 100 + i, [upper[0][i], upper[0][i + 1]], props
        )
        master_ids.append(c.Id)
    contact.AddConditions(slave_ids + master_ids)
    contact.AddNodes(lower[2] + upper[0])
    utils.SetFlag(ca.SLAVE, True, [main.GetCondition(i) for i in slave_ids])
    utils.SetFlag(ca.MASTER, False, [main.GetCondition(i) for i in slave_ids])
    utils.SetFlag(ca.MASTER, True, [main.GetCondition(i) for i in master_ids])
    utils.SetFlag(ca.SLAVE, False, [main.GetCondition(i) for i in master_ids])
    utils.SetFlag(ca.SLAVE, True, [main.GetNode(i) for i in lower[2]])
    utils.SetFlag(ca.MASTER, True, [main.GetNode(i) for i in upper[0]])
    return main


def _overlaps(main: ca.ModelPart, slave: int, master: int) -> bool:
    xs = [n.X for n in main.GetCondition(slave).GetGeometry()]
    xm = [n.X for n in main.GetCondition(master).GetGeometry()]
    return min(max(xs), max(xm)) - max(min(xs), min(xm)) > 1e-9


def test_contact_search_pairs_are_the_overlapping_faces() -> None:
    main = _two_blocks(8, 5, 0.004)
    settings = ca.ContactSearchSettings(
        type_search="in_radius_with_obb",
        check_gap="check_mapping",
        condition_name="ALMFrictionlessMortarContact",
    )
    search = ca.ContactSearchProcess(main, settings, main.GetProperties(1))
    search.ExecuteInitialize()
    search.ExecuteInitializeSolutionStep()
    pairs = {(s, m) for s, m, _ in search.GetPairs()}
    expected = {(s, m) for s in range(1, 9) for m in range(100, 105) if _overlaps(main, s, m)}
    assert pairs == expected
    assert len(expected) == 12  # 8 + 5 - 1 overlaps of two non-matching partitions of [0, 1]
    computing = search.GetComputingModelPart()
    assert computing.NumberOfConditions() == len(expected)
    for slave, master, pair_id in search.GetPairs():
        pair = main.GetCondition(pair_id)
        assert pair.IsPaired()
        assert [n.Id for n in pair.GetParentGeometry()] == [
            n.Id for n in main.GetCondition(slave).GetGeometry()
        ]
        assert [n.Id for n in pair.GetPairedGeometry()] == [
            n.Id for n in main.GetCondition(master).GetGeometry()
        ]
    # DISTANCE_THRESHOLD = max(mean h 1/8 slave, 1/5 master) = 0.2; L = 0.01 * 0.2 < gap 0.004.
    assert main.ProcessInfo[ca.DISTANCE_THRESHOLD] == pytest.approx(0.2)
    assert not any(main.GetNode(i).Is(ca.ACTIVE) for i in range(19, 28))
    timings = search.GetLastSearchTimings()
    assert timings["slave_faces"] == 8 and timings["master_faces"] == 5
    assert timings["total"] >= timings["tree_build"] + timings["queries"]


def test_contact_search_far_blocks_have_no_pairs() -> None:
    main = _two_blocks(4, 4, 1.0)
    search = ca.ContactSearchProcess(main, ca.ContactSearchSettings(type_search="in_radius"))
    search.Execute()
    assert search.GetPairs() == []


def test_contact_search_settings_fields_and_errors() -> None:
    settings = ca.ContactSearchSettings()
    assert settings.type_search == "in_radius"
    assert settings.check_gap == "check_mapping"
    assert settings.search_factor == 3.5 and settings.allocation_size == 1000
    settings.type_search = "InBoxWithOBB"
    assert settings.type_search == "in_box_with_obb"
    settings.bounding_box_factor = 0.5
    assert settings.bounding_box_factor == 0.5
    nested = ca.ContactSearchSettings.from_dict(
        {"check_gap": "direct_check", "octree_search_parameters": {"bounding_box_factor": 0.2}}
    )
    assert nested.check_gap == "direct_check" and nested.bounding_box_factor == 0.2
    with pytest.raises(
        ca.InputError, match='(?s)unknown key "serch_factor".*did you mean "search_factor"'
    ):
        ca.ContactSearchSettings(serch_factor=2.0)
    with pytest.raises(ca.InputError, match='unknown type_search "kdop"'):
        ca.ContactSearchSettings(type_search="kdop")
    with pytest.raises(ca.InputError, match="check_gap"):
        settings.check_gap = "mapping"
    with pytest.raises(ca.InputError, match="search_factor"):
        ca.ContactSearchSettings.from_dict({"search_factor": -1.0})


def test_mpc_contact_search_creates_constraints() -> None:
    main = _two_blocks(4, 4, -0.001)
    settings = ca.ContactSearchSettings(
        type_search="in_radius_with_obb", condition_name="ALMFrictionlessMortarContact"
    )
    search = ca.MPCContactSearchProcess(main, settings, main.GetProperties(1))
    search.ExecuteInitialize()
    search.ExecuteInitializeSolutionStep()
    assert isinstance(search, ca.ContactSearchProcess)
    n_pairs = len(search.GetPairs())
    assert n_pairs == search.GetComputingModelPart().NumberOfConditions() > 0
    assert search.GetComputingModelPart().NumberOfMasterSlaveConstraints() == n_pairs
    # Penetration 0.001 < L: every slave node (top row of the lower block) is active.
    assert all(main.GetNode(i).Is(ca.ACTIVE) for i in range(11, 16))
