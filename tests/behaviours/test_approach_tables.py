"""The approach's look at the table in a room of three: with a target (where a task says its
table is, in the odometry frame) the robot measures that table and no other."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import cast

import pytest
from tables_scene import TABLES, in_start_frame, matches, three_tables

from hfsm.primitive import Context
from hfsm_behaviours.approach.navigate import Look, look_at_table
from hfsm_behaviours.body import Body
from hfsm_sim.perception import TableSeen
from hfsm_sim.world import World


class StandStill:
    """The part of a primitive's Context that looking needs: waits advance the world."""

    def __init__(self, world: World, name: str) -> None:
        self.world, self.robot = world, world.robots[name]

    def wait(self, seconds: float | None = None) -> None:
        self.world.advance(seconds if seconds is not None else 0.05)

    def wait_until(self, ready: Callable[[], bool], timeout: float = math.inf) -> bool:
        waited = 0.0
        while not ready() and waited < timeout:
            self.world.advance(0.05)
            waited += 0.05
        return ready()


@pytest.mark.parametrize("index", range(len(TABLES)))
def test_look_at_table_measures_the_table_the_task_names(index: int) -> None:
    with three_tables() as world:
        body = Body(cast(Context, StandStill(world, "r1")))
        x, y = TABLES[index][:2]
        look = Look(pitch=0.25, spread=0.9, target=in_start_frame(x - 0.2, y + 0.3))
        rect = look_at_table(body, None, look)
        assert rect.found and matches(TableSeen(rect, False), TABLES[index])
        assert matches(TableSeen(look_at_table(body, rect, look), False), TABLES[index])


def test_no_table_where_the_task_names_none() -> None:
    with three_tables() as world:
        body = Body(cast(Context, StandStill(world, "r1")))
        look = Look(pitch=0.25, spread=0.9, target=in_start_frame(0.0, 1.5))
        assert not look_at_table(body, None, look).found
