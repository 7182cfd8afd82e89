"""Each carry primitive against the simulator, in a small scene at the table."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from carry_scene import at_table, machine_file, run_in_scene


def one_call(folder: Path, call: str, outcomes: list[str], timer: float = 120) -> Path:
    """A machine that calls one behaviour and ends in the outcome it gave."""
    arcs = ", ".join(f"{o}: {o}" for o in outcomes)
    return machine_file(folder, f"""
        outcomes: [{", ".join(dict.fromkeys([*outcomes, "timeout"]))}]
        timer: {timer}
        states:
          call:
            {call}
            on: {{{arcs}}}
    """)


def test_recentre_squares_up_at_grip_depth(tmp_path: Path) -> None:
    top = one_call(tmp_path, "do: recentre_to_middle_of_table", ["centred", "lost"])
    run = run_in_scene(top, at_table((0.0, 0.05, 12.0), None))
    assert run.outcome() == "centred"
    assert abs(run.poses["r1"].yaw) <= 5.0
    assert run.poses["r1"].depth == pytest.approx(0.08, abs=0.025)


def test_recentre_is_lost_without_a_table(tmp_path: Path) -> None:
    top = one_call(tmp_path, "do: recentre_to_middle_of_table", ["centred", "lost"])
    run = run_in_scene(top, at_table((0.0, 0.8, 0.0), None))
    assert run.outcome() == "lost"


@pytest.mark.parametrize("along", [0.14, -0.12])
def test_align_walks_to_the_middle(tmp_path: Path, along: float) -> None:
    top = one_call(tmp_path, "do: align_to_middle_of_table", ["aligned", "lost", "timeout"])
    run = run_in_scene(top, at_table((along, 0.0, 6.0), None))
    assert run.outcome() == "aligned"
    assert abs(run.poses["r1"].along) < 0.05  # 20 % of the longer side: |L - R| <= 0.09
    assert abs(run.poses["r1"].along) < abs(along)


def test_tighter_difference_walks_closer_to_the_middle(tmp_path: Path) -> None:
    call = "do: align_to_middle_of_table\n            with: {difference: 0.05}"
    top = one_call(tmp_path, call, ["aligned", "lost", "timeout"])
    run = run_in_scene(top, at_table((0.14, 0.0, 0.0), None))
    assert run.outcome() == "aligned"
    assert abs(run.poses["r1"].along) < 0.015


def test_lift_step_land_carries_the_table_level(tmp_path: Path) -> None:
    top = machine_file(tmp_path, """
        outcomes: [done, failure, timeout]
        timer: 60
        states:
          lift: {do: lift_table, on: {lifted: step, failure: failure}}
          step:
            do: small_step_sideways
            with: {direction: "${'left' if agent.id == 'r1' else 'right'}", steps: 3}
            watch: [{if: "not in.holding", then: failure}]
            on: {stepped: land}
          land: {do: land_table, on: {landed: done, failure: failure}}
    """)
    run = run_in_scene(top, at_table())
    assert (run.outcome("r1"), run.outcome("r2")) == ("done", "done")
    x, _, lift, _ = run.table
    assert x == pytest.approx(0.6 - 0.15, abs=0.01)  # r1's left is -x
    assert abs(lift) < 0.005 and not run.score["dropped"]


def test_lift_fails_out_of_reach(tmp_path: Path) -> None:
    top = one_call(tmp_path, "do: lift_table", ["lifted", "failure"])
    run = run_in_scene(top, at_table((0.0, 0.2, 0.0), None))
    assert run.outcome() == "failure"


def test_choose_carry_direction_picks_the_nearer_wall(tmp_path: Path) -> None:
    top = machine_file(tmp_path, """
        vars: {direction: ""}
        outcomes: [chosen, failure, timeout]
        outputs: {direction: "${vars.direction}"}
        timer: 30
        states:
          call: {do: choose_carry_direction, save: {direction: direction},
                 on: {chosen: chosen, failure: failure}}
    """)
    near_plus_x = run_in_scene(top, at_table())  # r1 faces +y: +x is its right
    assert near_plus_x.outputs() == {"direction": "right"}
    near_minus_x = run_in_scene(top, at_table(table_x=-0.9))
    assert near_minus_x.outputs() == {"direction": "left"}
    assert near_minus_x.outputs("r2") == {"direction": "right"}


def test_choose_carry_direction_passes_over_a_wall_behind(tmp_path: Path) -> None:
    """Issue 10 (a room of many tables): a wall close behind the robot, running along the carry,
    shows when it looks right and back; the table's end can never meet it, so the wall it can
    meet (left, the nearer end wall) is chosen."""
    top = machine_file(tmp_path, """
        vars: {direction: "", distance: 0.0}
        outcomes: [chosen, failure, timeout]
        outputs: {direction: "${vars.direction}", distance: "${vars.distance}"}
        timer: 30
        states:
          call: {do: choose_carry_direction, save: {direction: direction, distance: distance},
                 on: {chosen: chosen, failure: failure}}
    """)
    scene = {**at_table(r2=None, table_x=-0.9), "room": {"width": 5.0, "depth": 2.2}}  # wall 0.76 m behind
    chosen = run_in_scene(top, scene).outputs()
    assert chosen["direction"] == "left", "before: right, the wall behind taken for one 1.04 m away"
    assert chosen["distance"] == pytest.approx(1.6, abs=0.25), "the west wall, 1.6 m to the left"


def test_choose_carry_direction_toward_a_point(tmp_path: Path) -> None:
    """Issue 10: with `toward` (own start frame: r1 starts facing +y, so x is its right) the side
    of that point wins over the nearer wall, for a team that claimed a wall."""
    top = machine_file(tmp_path, """
        params: {toward: {type: list, default: []}}
        vars: {direction: ""}
        outcomes: [chosen, failure, timeout]
        outputs: {direction: "${vars.direction}"}
        timer: 30
        states:
          call: {do: choose_carry_direction, with: {toward: "${params.toward}"}, save: {direction: direction},
                 on: {chosen: chosen, failure: failure}}
    """)
    away_from_the_near_wall = run_in_scene(top, at_table(r2=None), params={"toward": [0.5, 3.0]})
    assert away_from_the_near_wall.outputs() == {"direction": "left"}, "the table's near wall is on r1's right"
    toward_it = run_in_scene(top, at_table(r2=None), params={"toward": [2.0, -1.0]})
    assert toward_it.outputs() == {"direction": "right"}


@pytest.mark.parametrize(("table_x", "outcome", "steps"),
                         [(0.6, "not_reached", 10), (1.85, "not_reached", 5), (2.07, "reached", 0)])
def test_table_at_wall(tmp_path: Path, table_x: float, outcome: str, steps: int) -> None:
    top = machine_file(tmp_path, """
        vars: {steps: -1, gap: -1.0}
        outcomes: [reached, not_reached, failure, timeout]
        outputs: {steps: "${vars.steps}", gap: "${vars.gap}"}
        timer: 30
        states:
          call:
            do: table_at_wall
            with: {direction: right}
            save: {steps: steps, gap: gap}
            on: {reached: reached, not_reached: not_reached, failure: failure}
    """)
    run = run_in_scene(top, at_table(table_x=table_x))
    gap = 2.5 - table_x - 0.4
    assert run.outcome() == outcome
    assert run.outputs()["gap"] == pytest.approx(gap, abs=0.03)
    assert run.outputs()["steps"] == pytest.approx(steps, abs=1)


def test_a_watch_on_the_hands_stops_the_step_when_the_table_is_stuck(tmp_path: Path) -> None:
    """A table turned 30 degrees meets the wall with a corner: both carriers feel it on their
    hands (a give of more than 2 cm, whatever its direction: step_together's watch), stop and
    land it, instead of walking on until the grip gives."""
    yaw, table_x = math.radians(30.0), 1.2
    nx, ny = -math.sin(yaw), math.cos(yaw)
    scenario = {"room": {"width": 4.0, "depth": 4.0}, "table": {"x": table_x, "yaw": 30.0},
                "jitter": {"position": 0.0, "yaw": 0.0},
                "robots": {"r1": {"x": table_x - 0.34 * nx, "y": -0.34 * ny, "yaw": 120.0},
                           "r2": {"x": table_x + 0.34 * nx, "y": 0.34 * ny, "yaw": -60.0}}}
    top = machine_file(tmp_path, """
        vars: {give: 0.0}
        outcomes: [stepped, blocked, failure, timeout]
        outputs: {give: "${vars.give}"}
        timer: 60
        states:
          lift: {do: lift_table, on: {lifted: step, failure: failure}}
          step:
            do: small_step_sideways
            with: {direction: "${'right' if agent.id == 'r1' else 'left'}", steps: 12}
            watch:
              - {if: "not in.holding", then: failure}
              - {if: "max(in.hand_give_left, in.hand_give_right) > 0.02", then: felt}
            on: {stepped: land_stepped}
          felt:
            do: set
            with: {give: "${max(in.hand_give_left, in.hand_give_right)}"}
            on: {done: land_blocked}
          land_stepped: {do: land_table, on: {landed: stepped, failure: failure}}
          land_blocked: {do: land_table, on: {landed: blocked, failure: failure}}
    """)
    run = run_in_scene(top, scenario)
    assert (run.outcome("r1"), run.outcome("r2")) == ("blocked", "blocked")
    assert all(0.02 < run.outputs(r)["give"] < 0.05 for r in ("r1", "r2"))
    assert not run.score["dropped"]
    assert run.score["table_wall_distance"] < 0.01
