"""Clear the room's held-back rooms (issue 10: "a held-back set of rooms (other sizes, table layouts,
failure times) must be cleared"). Issue 10's bench rooms (tools/room/scenes.py; the campaign now
draws from hfsm_sim/roomgen.py) never drew these; they were chosen by this rule before any of them was run, and are not changed to pass:

- sizes: 3-table rooms outside the bench's 8-9 x 5.75-6.75 m (10.5 x 7.5, 7 x 7, 11 x 5.5, 9.5 x 6.5),
  the 2-table room outside its 7-8 x 5-6 m (6.5 x 6.5);
- tables: at least one per room at a heading off 0/90/180/270 (20, 135, -30, 60, 160 deg), and
  sizes outside the bench's 0.7-1.0 x 0.45-0.55 m (1.2 x 0.6, 0.6 x 0.4, 1.1 x 0.55);
- robots: each pair 1.05-1.35 m from its table's centre line (the bench: 1.2) and facing it up to
  15 deg off (the bench: square on); 6, 7 and 8 robots for 3 tables, 5 for 2;
- failures: one robot each, at times the bench never draws (its times are 5-150 s to 0.1 s: here
  to 0.01 s, one at 163.52 s, one from the `rate:` form the bench's target rooms do not use);
- seeds: the room's index (0-4); rooms whose claimed corridors cross nothing (the bench's own rule
  of a room that can be cleared, checked below), so a miss is the team's, not the room's.

Each room is judged as the bench judges it (tools/room/trials.py, from the simulator's score):
every table within 0.15 m of a wall, nothing dropped except by a robot failing mid-carry, no
robot-robot contact; the named robot failed, and every other robot's machine ends `cleared`."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from hfsm_behaviours.room.claims import claim_walls, crossings  # noqa: E402
from hfsm_sim.scenario import scenario_from_dict  # noqa: E402
from tools.room.trials import RoomTrial, run_room_trial  # noqa: E402

REACH = 0.5  # clear_room's default `reach`

WIDE = """  # 3 tables, 7 robots, a 10.5 x 7.5 room; table1 1.2 x 0.6 at 20 deg, table3 0.6 x 0.4; r6 (table3's pair, a 4.5 m carry) fails at 163.52 s
task: table_to_wall
room: {width: 10.5, depth: 7.5}
tables:
- {id: table1, x: -3.2, y: -1.6, yaw: 20, length: 1.2, width: 0.6, priority: 1}
- {id: table2, x: 2.8, y: -2.1, yaw: 90, length: 0.8, width: 0.5, priority: 2}
- {id: table3, x: 0.4, y: 2.0, yaw: 0, length: 0.6, width: 0.4, priority: 3}
robots:
  r1: {x: -3.55, y: -0.34, yaw: -62, body: full}
  r2: {x: -2.66, y: -2.79, yaw: 106, body: full}
  r3: {x: 1.7, y: -2.25, yaw: 8, body: full}
  r4: {x: 3.9, y: -2.25, yaw: -178, body: full}
  r5: {x: 0.4, y: 3.25, yaw: -105, body: full}
  r6: {x: 0.4, y: 0.75, yaw: 95, body: full}
  r7: {x: -4.3, y: 2.8, yaw: 45, body: full}
jitter: {position: 0.1, yaw: 10}
failures:
- {robot: r6, at: 163.52, reason: held-back}
"""

SQUARE = """  # 3 tables, 6 robots, a 7 x 7 room; table1 at 135 deg, table2 1.2 x 0.6; r4 (table2's pair) fails at 23.37 s
task: table_to_wall
room: {width: 7.0, depth: 7.0}
tables:
- {id: table1, x: -1.8, y: -1.9, yaw: 135, length: 0.9, width: 0.5, priority: 1}
- {id: table2, x: 1.9, y: -1.0, yaw: 0, length: 1.2, width: 0.6, priority: 2}
- {id: table3, x: -0.2, y: 2.0, yaw: 90, length: 0.6, width: 0.4, priority: 3}
robots:
  r1: {x: -2.65, y: -2.75, yaw: 53, body: full}
  r2: {x: -0.95, y: -1.05, yaw: -147, body: full}
  r3: {x: 1.95, y: 0.35, yaw: -92, body: full}
  r4: {x: 1.95, y: -2.35, yaw: 92, body: full}
  r5: {x: -1.25, y: 1.9, yaw: 15, body: full}
  r6: {x: 0.85, y: 1.9, yaw: 175, body: full}
jitter: {position: 0.1, yaw: 10}
failures:
- {robot: r4, at: 23.37, reason: held-back}
"""

NARROW = """  # 3 tables, 8 robots, an 11 x 5.5 room; table1 at -30 deg, table3 1.2 x 0.6; r3 (table2's pair) at risk at 0.8 failures a minute (`rate:`; seed 2: it fails at 31.4 s)
task: table_to_wall
room: {width: 11.0, depth: 5.5}
tables:
- {id: table1, x: -3.5, y: 0.6, yaw: -30, length: 1.0, width: 0.5, priority: 1}
- {id: table2, x: 0.2, y: -1.1, yaw: 0, length: 0.7, width: 0.45, priority: 2}
- {id: table3, x: 3.6, y: 0.8, yaw: 90, length: 1.2, width: 0.6, priority: 3}
robots:
  r1: {x: -2.81, y: 1.59, yaw: -135, body: full}
  r2: {x: -4.01, y: -0.49, yaw: 65, body: full}
  r3: {x: 0.2, y: 0.05, yaw: -85, body: full}
  r4: {x: 0.2, y: -2.25, yaw: 95, body: full}
  r5: {x: 2.3, y: 0.8, yaw: 0, body: full}
  r6: {x: 4.9, y: 0.8, yaw: 166, body: full}
  r7: {x: -1.2, y: 2.0, yaw: 0, body: full}
  r8: {x: 0.9, y: 1.9, yaw: 180, body: full}
jitter: {position: 0.1, yaw: 10}
failures:
- rate: 0.8
  robots: [r3]
  reason: held-back
"""

OBLIQUE = """  # 3 tables, 8 robots, a 9.5 x 6.5 room; table2 1.0 x 0.6 at 60 deg, table3 1.1 x 0.55 at 160 deg; r5 (table3's pair) fails at 88.41 s
task: table_to_wall
room: {width: 9.5, depth: 6.5}
tables:
- {id: table1, x: -2.9, y: 1.5, yaw: 0, length: 0.8, width: 0.5, priority: 1}
- {id: table2, x: -0.5, y: -1.5, yaw: 60, length: 1.0, width: 0.6, priority: 2}
- {id: table3, x: 2.9, y: 1.0, yaw: 160, length: 1.1, width: 0.55, priority: 3}
robots:
  r1: {x: -2.9, y: 2.7, yaw: -90, body: full}
  r2: {x: -2.9, y: 0.3, yaw: 90, body: full}
  r3: {x: -1.55, y: -0.72, yaw: -45, body: full}
  r4: {x: 0.7, y: -2.02, yaw: 169, body: full}
  r5: {x: 2.52, y: -0.03, yaw: 76, body: full}
  r6: {x: 3.28, y: 2.03, yaw: -116, body: full}
  r7: {x: -4.0, y: -2.4, yaw: 90, body: full}
  r8: {x: 4.2, y: -2.5, yaw: 180, body: full}
jitter: {position: 0.1, yaw: 10}
failures:
- {robot: r5, at: 88.41, reason: held-back}
"""

TWO = """  # 2 tables, 5 robots, a 6.5 x 6.5 room; table1 1.1 x 0.55 at 60 deg, table2 at 180 deg; r2 (table1's pair) fails at 57.93 s
task: table_to_wall
room: {width: 6.5, depth: 6.5}
tables:
- {id: table1, x: -1.4, y: -1.0, yaw: 60, length: 1.1, width: 0.55, priority: 1}
- {id: table2, x: 1.5, y: 1.6, yaw: 180, length: 0.7, width: 0.45, priority: 2}
robots:
  r1: {x: -2.48, y: -0.37, yaw: -30, body: full}
  r2: {x: -0.32, y: -1.62, yaw: 165, body: full}
  r3: {x: 1.4, y: 0.4, yaw: 75, body: full}
  r4: {x: 1.4, y: 2.8, yaw: -85, body: full}
  r5: {x: 2.0, y: -2.3, yaw: 135, body: full}
jitter: {position: 0.1, yaw: 10}
failures:
- {robot: r2, at: 57.93, reason: held-back}
"""

CASES = [("wide", WIDE, 0, "r6"), ("square", SQUARE, 1, "r4"), ("narrow", NARROW, 2, "r3"),
         ("oblique", OBLIQUE, 3, "r5"), ("two", TWO, 4, "r2")]
IDS = [c[0] for c in CASES]
# `wide` was cleared with robot-robot contacts before (a helper pushing the failed robot aside); since a
# survivor whose slide fails steps back in and slides again (room_carry's step_back), it is cleared
# without one (314.45 s), so every room's contacts are asserted.


def scenario(text: str) -> dict[str, Any]:
    data: dict[str, Any] = yaml.safe_load(text)
    return data


@pytest.mark.parametrize(("name", "text", "seed", "robot"), CASES, ids=IDS)
def test_a_held_back_room_can_be_cleared_as_the_team_clears_rooms(name: str, text: str, seed: int,
                                                                   robot: str) -> None:
    data = scenario(text)
    failures = scenario_from_dict(data).failure_times(seed)
    assert [r for _, r, _ in failures] == [robot]
    tables = data["tables"]
    ways = claim_walls(tables, data["room"]["width"], data["room"]["depth"], REACH)
    assert crossings(list(ways.values()), tables, REACH) == 0


@pytest.mark.slow
@pytest.mark.parametrize(("name", "text", "seed", "robot"), CASES, ids=IDS)
def test_a_held_back_room_is_cleared(name: str, text: str, seed: int, robot: str) -> None:
    result = run_room_trial(RoomTrial("held-back", name, seed, scenario(text)))
    assert result["cleared"], (result["distances"], result["dropped"], result.get("endings"))
    assert result["collisions"] == 0
    assert set(result["failed"]) == {robot}
    assert {a: o for a, o in result["outcomes"].items() if a != robot} == dict.fromkeys(
        sorted(set(result["outcomes"]) - {robot}), "cleared")
