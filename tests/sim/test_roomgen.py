"""The room generator: every room valid and within the issue's ranges, each stratum what it says."""

from __future__ import annotations

import itertools
import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hfsm_sim import roomgen
from hfsm_sim.roomgen import STRATA, Table, draw, point_gap, polygon_gap
from hfsm_sim.scenario import load_scenario, scenario_from_dict

SEEDS = range(1, 31)


def _tables(data: dict) -> list[Table]:
    return [Table(t["x"], t["y"], t["yaw"], t["length"], t["width"]) for t in data["tables"]]


def _gaps(data: dict) -> list[float]:
    tables = _tables(data)
    return [polygon_gap(a.corners(), b.corners()) for a, b in itertools.combinations(tables, 2)]


def _wall_gaps(data: dict) -> list[float]:
    w, d = data["room"]["width"], data["room"]["depth"]
    return [min(t.wall_gaps(w, d)) for t in _tables(data)]


@pytest.mark.parametrize("stratum", list(STRATA))
def test_every_room_is_valid_and_within_the_ranges(stratum: str) -> None:
    for seed in SEEDS:
        data = draw(seed, stratum)
        scenario_from_dict(data)
        w, d = data["room"]["width"], data["room"]["depth"]
        assert 6.0 <= w <= 16.0 and 4.0 <= d <= 12.0
        k, n = len(data["tables"]), len(data["robots"])
        assert 1 <= k <= 6 and 2 * k <= n <= min(16, 2 * k + 4)
        for t in data["tables"]:
            assert 0.6 <= t["length"] <= 1.5 and 0.4 <= t["width"] <= min(0.9, t["length"])
        assert all(g >= 0.7 for g in _gaps(data)) and all(g >= 0.3 for g in _wall_gaps(data))
        robots = list(data["robots"].values())
        for a, b in itertools.combinations(robots, 2):
            assert math.hypot(a["x"] - b["x"], a["y"] - b["y"]) >= 0.8 - 1e-9
        for r in robots:
            assert all(point_gap((r["x"], r["y"]), t.corners()) >= 0.5 for t in _tables(data))
            assert -180 <= r["yaw"] < 180
        loss = data.get("radio", {}).get("loss", 0.0)
        assert 0.0 <= loss <= 0.3


def test_each_stratum_draws_what_it_names() -> None:
    for seed in SEEDS:
        assert min(_gaps(draw(seed, "close"))) <= 1.0
        assert min(_wall_gaps(draw(seed, "walls"))) <= 0.6
        narrow = draw(seed, "narrow")["room"]
        assert narrow["depth"] <= 5.0 and narrow["width"] >= 9.0
        crowded = list(draw(seed, "crowded")["robots"].values())
        near = [min(math.hypot(a["x"] - b["x"], a["y"] - b["y"]) for b in crowded if b is not a) for a in crowded]
        assert sum(d <= 1.02 for d in near) >= len(near) - 1  # a grid of 0.8-1.0 m (tables may cut it)
        failures = draw(seed, "failures")["failures"]
        assert failures and ((len(failures) in (1, 2) and all("at" in f for f in failures))
                             or ("rate" in failures[0] and 0.005 <= failures[0]["rate"] <= 0.05))
        assert 0.05 <= draw(seed, "loss")["radio"]["loss"] <= 0.3
        for stratum in ("open", "close", "walls", "narrow", "crowded"):
            data = draw(seed, stratum)
            assert not data["failures"] and "radio" not in data


def test_the_draws_cover_the_ranges() -> None:
    rooms = [draw(seed, s) for seed in range(1, 41) for s in STRATA]
    assert {len(r["tables"]) for r in rooms} == set(range(1, 7))
    assert max(len(r["robots"]) for r in rooms) == 16
    yaws = {t["yaw"] % 90 for r in rooms for t in r["tables"]}
    assert len(yaws) > 40  # any heading, not the four right angles
    kinds = {("rate" if "rate" in r["failures"][0] else len(r["failures"])) for r in rooms if r["failures"]}
    assert kinds == {1, 2, "rate"}


def test_a_seed_always_draws_the_same_room() -> None:
    assert draw(7, "mixed") == draw(7, "mixed")
    assert draw(7, "mixed") != draw(8, "mixed")
    assert draw(7, "walls") != draw(7, "close")
    with pytest.raises(ValueError, match="unknown stratum"):
        draw(1, "cramped")


def test_a_room_is_an_ordinary_scenario_file(tmp_path: Path) -> None:
    path = tmp_path / "loss-3.yaml"
    roomgen.write(path, draw(3, "loss"))
    scenario = load_scenario(path)
    assert scenario.radio.loss == draw(3, "loss")["radio"]["loss"] > 0
    assert len(scenario.all_tables) == len(draw(3, "loss")["tables"])


def test_polygon_gap() -> None:
    square = Table(0.0, 0.0, 0.0, 1.0, 1.0).corners()
    assert polygon_gap(square, Table(2.0, 0.0, 0.0, 1.0, 1.0).corners()) == pytest.approx(1.0)
    assert polygon_gap(square, Table(0.5, 0.5, 45.0, 1.0, 1.0).corners()) == 0.0
    assert polygon_gap(square, Table(2.0, 2.0, 0.0, 1.0, 1.0).corners()) == pytest.approx(math.sqrt(2))
    assert point_gap((0.0, 0.0), square) == 0.0 and point_gap((1.5, 0.0), square) == pytest.approx(1.0)


@settings(max_examples=60, deadline=None)
@given(st.floats(-3, 3), st.floats(-3, 3), st.floats(0, 360), st.floats(0, 360))
def test_polygon_gap_is_never_more_than_between_any_two_corners(x: float, y: float, a: float, b: float) -> None:
    one, two = Table(0.0, 0.0, a, 1.2, 0.5).corners(), Table(x, y, b, 0.8, 0.6).corners()
    gap = polygon_gap(one, two)
    assert gap <= min(math.dist(p, q) for p in one for q in two) + 1e-9
    assert gap == pytest.approx(polygon_gap(two, one), abs=1e-9)


def test_the_scenario_radio_loss_is_the_worlds_unless_the_run_gives_one() -> None:
    from hfsm_sim import World

    data = {**draw(1, "open"), "radio": {"loss": 0.25}}
    scenario = scenario_from_dict(data)
    with World(scenario, 0) as world:
        assert world.radio.loss == 0.25
    with World(scenario, 0, radio_loss=0.1) as world:
        assert world.radio.loss == 0.1
    with pytest.raises(ValueError, match="loss"):
        scenario_from_dict({**data, "radio": {"loss": 1.5}})


def test_the_world_holds_the_largest_rooms_drawn() -> None:
    from hfsm_sim import World

    big = next(d for d in (draw(s, "mixed") for s in range(1, 200)) if len(d["tables"]) == 6 and len(d["robots"]) == 16)
    with World(scenario_from_dict(big), 0) as world:
        world.advance(0.5)
        assert len(world.robots) == 16 and world.score()["robot_collisions"] == 0
        tables = world.poses()["tables"]
        assert [round(t[2] * 180 / math.pi) % 360 for t in tables] == [round(t["yaw"]) % 360 for t in big["tables"]]
