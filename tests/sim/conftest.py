from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Any

import pytest

from hfsm_sim.scenario import Scenario, scenario_from_dict
from hfsm_sim.world import World


def make_scenario(robots: dict[str, dict[str, float]], **extra: Any) -> Scenario:
    return scenario_from_dict({"room": {"width": 4.0, "depth": 4.0}, "robots": robots, **extra})


@pytest.fixture
def world_factory() -> Iterator[Callable[..., World]]:
    worlds: list[World] = []

    def make(robots: dict[str, dict[str, float]], seed: int = 0, **kwargs: Any) -> World:
        scenario_extra = {k: kwargs.pop(k) for k in ("table", "room", "jitter") if k in kwargs}
        world = World(make_scenario(robots, **scenario_extra), seed, **kwargs)
        worlds.append(world)
        return world

    yield make
    for world in worlds:
        world.close()
