"""Several tables in view: each told apart with its place, heading and size in the robot's
odometry frame, and the one a task names picked by where it is (scene: tests/tables_scene.py)."""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from tables_scene import START, TABLES, in_start_frame, matches, three_tables

from hfsm_sim.perception import PerceptionConfig, components, top_face
from hfsm_sim.perception.table_rect import TableRect
from hfsm_sim.perception.tables import Piece, TableSeen, group_pieces, pick_table, see_tables
from hfsm_sim.world import World

HEAD_YAWS = (-0.9, 0.0, 0.9)


@pytest.fixture
def world() -> Iterator[World]:
    with three_tables() as w:
        yield w


def look_around(world: World, name: str = "r1", pitch: float = 0.25) -> list[TableSeen]:
    robot = world.robots[name]
    views = []
    for yaw in HEAD_YAWS:
        robot.set_head(yaw, pitch)
        world.advance(1.0)
        views.append((robot.image("forward"), robot.camera_model("forward")))
    return see_tables(views)


def test_three_tables_told_apart_with_place_heading_and_size(world: World) -> None:
    seen = look_around(world)
    assert len(seen) == 3
    for truth in TABLES:
        assert sum(matches(s, truth) for s in seen) == 1, truth
    distances = [math.hypot(s.rect.x, s.rect.y) for s in seen]
    assert distances == sorted(distances)


@pytest.mark.parametrize("index", range(len(TABLES)))
def test_a_task_names_its_table_by_an_approximate_place(world: World, index: int) -> None:
    seen = look_around(world)
    x, y = TABLES[index][:2]
    near = in_start_frame(x + 0.3, y - 0.25)          # the task knows the place roughly
    picked = pick_table(seen, near, gate=0.6)
    assert picked is not None and matches(picked, TABLES[index])
    assert pick_table(seen, in_start_frame(0.0, 2.5), gate=0.6) is None   # nothing there


def test_a_robot_in_front_of_a_table_does_not_split_it() -> None:
    """r2 stands between r1 and the middle table and cuts its top in two in the image."""
    robots = {"r1": {"x": START[0], "y": START[1], "yaw": START[2]},
              "r2": {"x": 0.0, "y": -0.5, "yaw": -90.0}}
    with three_tables(robots) as world:
        robot = world.robots["r1"]
        robot.set_head(0.0, 0.25)
        world.advance(1.0)
        image = robot.image("forward")
        assert components(top_face(image))[1].size == 2
        seen = see_tables([(image, robot.camera_model("forward"))])
    assert len(seen) == 1 and matches(seen[0], TABLES[0])


def test_no_tables_in_a_blank_view(world: World) -> None:
    camera = world.robots["r1"].camera_model("forward")
    assert see_tables([(np.zeros((120, 160, 3), np.uint8), camera)]) == []
    assert see_tables([]) == []


def square(cx: float, cy: float, half: float) -> np.ndarray:
    t = np.linspace(-half, half, 20)
    edges = [np.column_stack([t, np.full_like(t, s * half)]) for s in (-1, 1)]
    edges += [np.column_stack([np.full_like(t, s * half), t]) for s in (-1, 1)]
    return np.concatenate(edges) + np.array([cx, cy])


@given(order=st.permutations(range(4)), spacing=st.floats(0.8, 3.0))
def test_pieces_group_by_gap_in_any_order(order: list[int], spacing: float) -> None:
    """Two tables (0.2 m or more apart), each seen as two overlapping pieces: two groups in any order."""
    pieces = [Piece(square(0.0, 0.0, 0.2), False), Piece(square(0.1, 0.0, 0.2), True),
              Piece(square(spacing, 0.0, 0.2), False), Piece(square(spacing + 0.05, 0.1, 0.2), False)]
    groups = group_pieces([pieces[i] for i in order], PerceptionConfig(table_gap=0.15))
    assert len(groups) == 2
    assert sorted(len(g.points) for g in groups) == [160, 160]
    assert sorted(g.clipped for g in groups) == [False, True]


@pytest.mark.parametrize(("spacing", "one"), [(0.7, True), (1.0, False)])
def test_pieces_a_robot_joins_are_one_table_if_no_larger_than_one(spacing: float, one: bool) -> None:
    """Two 0.2 m pieces either side of a robot (the same bridge label), `spacing` apart: one
    table up to `table_max_size`, beyond it two tables beside the robot."""
    bridge = frozenset([(0, 1)])
    pieces = [Piece(square(0.0, 0.0, 0.1), False, bridge), Piece(square(spacing, 0.0, 0.1), False, bridge)]
    groups = group_pieces(pieces, PerceptionConfig(table_max_size=(1.0, 0.6)))
    assert len(groups) == (1 if one else 2)


@given(x=st.floats(-3, 3), y=st.floats(-3, 3), gate=st.floats(0.1, 2.0))
def test_pick_table_is_the_nearest_within_the_gate(x: float, y: float, gate: float) -> None:
    tables = [TableSeen(TableRect(True, tx, ty, 0.0, 0.8, 0.5, 8), False)
              for tx, ty in ((0.0, 0.0), (1.5, 0.5), (-1.0, 2.0))]
    picked = pick_table(tables, (x, y), gate)
    nearest = min(tables, key=lambda t: math.dist(t.position, (x, y)))
    if math.dist(nearest.position, (x, y)) <= gate:
        assert picked is nearest
    else:
        assert picked is None


