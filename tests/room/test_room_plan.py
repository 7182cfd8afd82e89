"""The room's pure code: frames, claimed walls, pairs and help (hfsm_behaviours/room)."""

from __future__ import annotations

import itertools
import math
import random

import pytest
from hypothesis import given
from hypothesis import strategies as st

from hfsm_behaviours.room.claims import Rect, claim_walls, overlap
from hfsm_behaviours.room.frames import at_wall, difficulty_of, relocalise, to_local, to_room
from hfsm_behaviours.room.plan import drawn, make_room_plan, tables_of
from hfsm_behaviours.room.recovery import TRIES, groups_after, job_of, slide_of, sliding_partners, tried

ROOM = {"width": 7.0, "depth": 5.0}
TASKS = [
    {"id": "table1", "kind": "table", "x": -1.6, "y": 0.0, "yaw": 0, "length": 0.8, "width": 0.5, "priority": 1},
    {"id": "table2", "kind": "table", "x": 1.6, "y": 0.0, "yaw": 0, "length": 1.0, "width": 0.6, "priority": 2},
    {"id": "spot", "kind": "target", "x": 0.0, "y": 2.0, "difficulty": 0.5, "priority": 3},
]


def states(*places: tuple[str, float, float]) -> dict[str, dict[str, object]]:
    return {r: {"x": x, "y": y, "energy": 1.0, "record": {}} for r, x, y in places}


FOUR = states(("r1", -1.4, -1.2), ("r2", -1.8, 1.2), ("r3", 1.8, -1.2), ("r4", 1.4, 1.2))
SIX = {**FOUR, **states(("r5", -2.5, -1.8), ("r6", 2.5, -1.8))}


@given(st.floats(-5, 5), st.floats(-5, 5), st.floats(-180, 180), st.floats(-5, 5), st.floats(-5, 5))
def test_frames_round_trip(x: float, y: float, yaw: float, px: float, py: float) -> None:
    start = {"x": x, "y": y, "yaw": yaw}
    back = to_room(start, to_local(start, [px, py]))
    assert math.dist(back, [px, py]) < 1e-4


def test_a_point_ahead_of_a_robot_facing_north_is_on_its_x_axis() -> None:
    assert to_local({"x": 1.0, "y": 1.0, "yaw": 90}, [1.0, 3.0]) == [2.0, 0.0]


def test_larger_tables_are_harder() -> None:
    assert 0 < difficulty_of(0.6, 0.4) < difficulty_of(0.8, 0.5) < difficulty_of(1.2, 0.6) < 1
    assert [t["id"] for t in tables_of(TASKS)] == ["table1", "table2"]  # targets are no tables


def test_tables_in_line_go_to_opposite_walls() -> None:
    ways = claim_walls(tables_of(TASKS), 7.0, 5.0)
    assert ways["table1"].toward == (-3.5, 0.0) and ways["table2"].toward == (3.5, 0.0)
    assert math.isclose(ways["table1"].travel, 3.5 - 1.6 - 0.4)


def test_a_table_never_crosses_another_for_a_shorter_way() -> None:
    # table2's nearer wall is west, but table1 stands in the way: it goes east, table1 west
    tables = [{"id": "table1", "x": -2.0, "y": 0.0, "yaw": 0}, {"id": "table2", "x": -0.5, "y": 0.0, "yaw": 0}]
    ways = claim_walls(tables, 7.0, 5.0)
    assert ways["table1"].sign == -1 and ways["table2"].sign == 1
    assert not overlap(ways["table1"].corridor, ways["table2"].corridor)


def test_rectangles_overlap_when_turned() -> None:
    a = Rect(0, 0, 1, 0, 1, 0.2)
    turned = Rect(0.9, 0.9, math.cos(math.pi / 4), math.sin(math.pi / 4), 1, 0.2)
    assert overlap(a, turned) and not overlap(a, Rect(0, 1, 1, 0, 1, 0.2))


def test_the_plan_pairs_robots_and_keeps_spares() -> None:
    # no history: every relevance ties, and the robots standing at a table pair up for it (not by id)
    plan = make_room_plan(SIX, TASKS, ROOM)
    jobs = {r: job_of(plan, r, [], [], {}) for r in SIX}
    assert {r: (j["role"], j["table"]) for r, j in jobs.items() if j} == {
        "r1": ("leader", "table1"), "r2": ("assistant", "table1"), "r5": ("spare", "table1"),
        "r3": ("leader", "table2"), "r4": ("assistant", "table2"), "r6": ("spare", "table2")}
    assert jobs["r1"]["channel"] == jobs["r2"]["channel"] == "table1_r1_r2_"


def test_ties_of_relevance_pair_the_robots_of_one_table_not_r1_with_r10() -> None:
    tables = [{"id": f"table{i}", "x": 2.0 * i, "y": 0.0, "yaw": 90, "length": 0.8, "width": 0.5} for i in range(1, 6)]
    places = {f"r{2 * i - 1}": (2.0 * i, -1.2) for i in range(1, 6)} | {f"r{2 * i}": (2.0 * i, 1.2) for i in range(1, 6)}
    plan = make_room_plan(states(*((r, x, y) for r, (x, y) in places.items())), tables, {"width": 14.0, "depth": 6.0})
    for r in places:
        job = job_of(plan, r, [], [], {})
        assert job is not None and math.dist(places[r], (job["at"][0], job["at"][1])) < 1.3


def test_a_group_lends_its_spare_never_its_assistant_at_work() -> None:
    # table2's group (r3, r4, r6) keeps its pair when table1's assistant and spare are lost: r6 goes
    plan = make_room_plan(SIX, TASKS, ROOM)
    groups = groups_after(plan, ["r2", "r5"], [])
    assert [g["members"] for g in groups] == [["r1", "r6"], ["r3", "r4"]]


def test_a_spare_replaces_a_lost_assistant_and_7a_a_lost_leader() -> None:
    plan = make_room_plan(SIX, TASKS, ROOM)
    assistant_lost = {r: job_of(plan, r, ["r2"], [], {}) for r in ("r1", "r5")}
    assert [(j["role"], j["partner"]) for j in assistant_lost.values() if j] == [("leader", "r5"), ("assistant", "r1")]
    leader_lost = job_of(plan, "r2", ["r1"], [], {})
    assert leader_lost is not None and (leader_lost["role"], leader_lost["partner"]) == ("leader", "r5")
    assert job_of(plan, "r1", ["r1"], [], {}) is None


def test_a_short_group_borrows_from_a_finished_table_and_the_table_where_it_was_seen() -> None:
    plan = make_room_plan(FOUR, TASKS, ROOM)
    assert job_of(plan, "r1", ["r2"], [], {})["role"] == "spare"  # alone: waits
    job = job_of(plan, "r1", ["r2"], ["table2"], {"table1": [-2.0, 0.3]})
    helper = job_of(plan, "r3", ["r2"], ["table2"], {"table1": [-2.0, 0.3]})
    assert job is not None and helper is not None
    assert (job["role"], job["partner"], job["at"]) == ("leader", "r3", [-2.0, 0.3])
    assert (helper["role"], helper["channel"]) == ("assistant", "table1_r1_r3_")


def test_the_same_news_in_any_order_gives_the_same_jobs() -> None:
    plan = make_room_plan(SIX, TASKS, ROOM)
    for lost in itertools.permutations(["r2", "r4"]):
        assert [g["members"] for g in groups_after(plan, list(lost), [])] == [["r1", "r5"], ["r3", "r6"]]


def test_a_pair_tries_again_on_a_new_channel_once_both_gave_up() -> None:
    plan = make_room_plan(FOUR, TASKS, ROOM)
    first = "table1_r1_r2_"
    assert job_of(plan, "r1", [], [], {}, [f"{first}/r1"])["channel"] == first  # r2 still carries
    again = job_of(plan, "r1", [], [], {}, [f"{first}/r1", f"{first}/r2"])
    assert again["channel"] == "table1_r1_r2_1_"
    third = job_of(plan, "r2", [], [], {}, [f"{first}/r1", f"{first}/r2", "table1_r1_r2_1_/r1", "table1_r1_r2_1_/r2"])
    assert third["channel"] == "table1_r1_r2_2_"


FIRST = "table1_r1_r2_"
R1_SLIDES = slide_of("table1", FIRST, "r1", "r2")


def test_no_helper_is_lent_to_a_table_its_survivor_slides() -> None:
    plan = make_room_plan(FOUR, TASKS, ROOM)
    helped = job_of(plan, "r3", ["r2"], ["table2"], {})
    assert helped is not None and (helped["role"], helped["partner"]) == ("assistant", "r1")
    kept = {r: job_of(plan, r, ["r2"], ["table2"], {}, [], [R1_SLIDES]) for r in ("r1", "r3", "r4")}
    assert {r: (j["role"], j["table"]) for r, j in kept.items() if j} == {
        "r1": ("leader", "table1"), "r3": ("idle", "table2"), "r4": ("idle", "table2")}
    assert kept["r1"] is not None and kept["r1"]["channel"] == FIRST  # its own pairing goes on
    assert job_of(plan, "r2", ["r2"], [], {}, [], [R1_SLIDES]) is None  # the failed robot stays lost


def test_a_slide_ends_with_its_table_done_its_pairing_spent_or_its_survivor_lost() -> None:
    assert sliding_partners(["r2"], [], [], [R1_SLIDES]) == {"r2"}
    assert sliding_partners(["r2"], ["table1"], [], [R1_SLIDES]) == set()
    assert sliding_partners(["r2"], [], [f"{FIRST}/r1"], [R1_SLIDES]) == set()
    assert sliding_partners(["r1", "r2"], [], [], [R1_SLIDES]) == set()
    assert sliding_partners([], [], [], ["not/a slide"]) == set()
    plan = make_room_plan(FOUR, TASKS, ROOM)
    failed = job_of(plan, "r3", ["r2"], ["table2"], {}, [f"{FIRST}/r1"], [R1_SLIDES])
    assert failed is not None and (failed["role"], failed["partner"]) == ("assistant", "r1")  # help comes
    spare = job_of(make_room_plan(SIX, TASKS, ROOM), "r5", ["r2"], [], {}, [], [R1_SLIDES])
    assert spare is not None and spare["role"] == "spare"  # the group's spare is not lent either


NEWS = st.fixed_dictionaries({
    "lost": st.lists(st.sampled_from(sorted(SIX)), max_size=3),
    "done": st.lists(st.sampled_from(["table1", "table2"]), max_size=2),
    "spent": st.lists(st.sampled_from([f"{FIRST}/r1", f"{FIRST}/r2", "table2_r4_r5_/r4"]), max_size=3),
    "sliding": st.lists(st.sampled_from([R1_SLIDES, slide_of("table1", FIRST, "r2", "r1"),
                                         slide_of("table2", "table2_r4_r5_", "r4", "r5")]), max_size=3)})


@given(NEWS, st.randoms())
def test_jobs_are_the_same_for_the_same_news_heard_in_any_order(news: dict[str, list[str]], rnd: random.Random) -> None:
    plan = make_room_plan(SIX, TASKS, ROOM)
    shuffled = {k: rnd.sample(v, len(v)) + v[:1] for k, v in news.items()}
    for robot in sorted(SIX):
        assert job_of(plan, robot, news["lost"], news["done"], {}, news["spent"], news["sliding"]) == job_of(
            plan, robot, shuffled["lost"], shuffled["done"], {}, shuffled["spent"], shuffled["sliding"])


@given(st.floats(-3, 3), st.floats(-3, 3), st.floats(-170, 170), st.floats(-0.3, 0.3), st.floats(-0.3, 0.3),
       st.floats(-15, 15), st.sampled_from([0.0, 90.0, 30.0]))
def test_a_table_seen_where_it_is_known_to_stand_corrects_the_start(
        x: float, y: float, yaw: float, dx: float, dy: float, dyaw: float, table_yaw: float) -> None:
    truth = {"x": x, "y": y, "yaw": yaw}
    told = {"x": x + dx, "y": y + dy, "yaw": yaw + dyaw}
    known = [1.0, 2.0]
    seen = to_local(truth, known)
    heading = (table_yaw - yaw + 90.0) % 180.0 - 90.0 + 180.0  # the long axis either way round
    fixed = relocalise(told, seen, heading, known, table_yaw)
    assert math.dist((fixed["x"], fixed["y"]), (x, y)) < 1e-4
    assert abs((fixed["yaw"] - yaw + 180.0) % 360.0 - 180.0) < 1e-4


def test_a_table_at_its_wall_stands_on_its_way_a_little_off_the_wall() -> None:
    table = {"x": -1.6, "y": 0.3, "length": 0.8, "toward": [-3.5, 0.3]}
    assert at_wall(table) == pytest.approx([-3.05, 0.3])


def test_two_tables_left_short_make_one_pair_of_their_survivors() -> None:
    # r2 (table1) and r4 (table2) fail before either table is done: r1 and r3 pair up for table1
    plan = make_room_plan(FOUR, TASKS, ROOM)
    groups = groups_after(plan, ["r2", "r4"], [])
    assert [g["members"] for g in groups] == [["r1", "r3"], []]
    jobs = {r: job_of(plan, r, ["r2", "r4"], [], {}) for r in ("r1", "r3")}
    assert [(j["role"], j["table"], j["partner"]) for j in jobs.values() if j] == [
        ("leader", "table1", "r3"), ("assistant", "table1", "r1")]
    after = {r: job_of(plan, r, ["r2", "r4"], ["table1"], {}) for r in ("r1", "r3")}
    assert {(j["role"], j["table"]) for j in after.values() if j} == {("leader", "table2"), ("assistant", "table2")}


def test_with_no_pair_left_every_robot_alive_is_stuck_and_says_which_table() -> None:
    plan = make_room_plan(FOUR, TASKS, ROOM)
    job = job_of(plan, "r1", ["r2", "r3", "r4"], [], {})
    assert job is not None and job["role"] == "stuck" and job["stuck"] == "table1"
    assert job["why"] == "table1 needs two robots to lift it and 1 robot left alive (r1)"
    done_first = job_of(plan, "r1", ["r2", "r3", "r4"], ["table1"], {})
    assert done_first is not None and (done_first["role"], done_first["stuck"]) == ("stuck", "table2")
    assert job_of(plan, "r1", ["r2", "r3", "r4"], ["table1", "table2"], {})["role"] == "idle"  # all done


def test_a_survivor_sliding_its_table_alone_is_not_stuck() -> None:
    plan = make_room_plan(FOUR, TASKS, ROOM)
    channel = job_of(plan, "r1", [], [], {})["channel"]
    slide = slide_of("table1", channel, "r1", "r2")
    job = job_of(plan, "r1", ["r2", "r3", "r4"], [], {}, [], [slide])
    assert job is not None and job["role"] == "leader"
    ended = job_of(plan, "r1", ["r2", "r3", "r4"], [], {}, [f"{channel}/r1"], [slide])
    assert ended is not None and ended["role"] == "stuck"  # the slide failed: nobody is left to help


def tries_of(table: str, leader: str, assistant: str, n: int) -> list[str]:
    """`spent` after `n` pairings of one pair on `table` that both robots gave up."""
    base = f"{table}_{leader}_{assistant}_"
    return [f"{base}{k}_/{r}" if k else f"{base}/{r}" for k in range(n) for r in (leader, assistant)]


def test_a_table_tried_too_often_is_given_up_and_its_robots_help_the_others() -> None:
    """Held-out room walls-40000: table3's pair, sent to a place the table had been pushed off, tried
    again and again until the time limit. After TRIES pairings of one table ended without it at its
    wall the team gives it up; its robots are free for the tables left, and once only given-up
    tables are left the room ends `stuck`, saying which and why."""
    plan = make_room_plan(FOUR, TASKS, ROOM)
    assert tried([], tries_of("table1", "r1", "r2", TRIES - 1), ["table1", "table2"]) == {}
    spent = tries_of("table1", "r1", "r2", TRIES)
    assert tried([], spent, ["table1", "table2"]) == {"table1": TRIES}
    assert tried(["table1"], spent, ["table1", "table2"]) == {}  # done after all
    assert tried([], [f"{spent[0].split('/')[0]}/r1"] * 9, ["table1", "table10"]) == {}  # one channel is one try
    mid = job_of(plan, "r2", ["r3"], [], {}, spent)  # table2 has lost r3: r2, nearer r4, helps it
    assert mid is not None and (mid["role"], mid["table"], mid["partner"]) == ("assistant", "table2", "r4")
    idle = job_of(plan, "r1", ["r3"], [], {}, spent)
    assert idle is not None and idle["role"] == "idle"
    ended = job_of(plan, "r2", [], ["table2"], {}, spent)
    assert ended is not None and (ended["role"], ended["stuck"]) == ("stuck", "table1")
    assert ended["why"] == f"table1: {TRIES} tries by its pairs ended without it at its wall"
    going = job_of(plan, "r3", [], [], {}, spent)  # table2 not done yet: its pair carries on
    assert going is not None and (going["role"], going["table"]) == ("leader", "table2")


def test_what_the_monitor_draws_of_a_belief() -> None:
    plan = make_room_plan(FOUR, TASKS, ROOM)
    job = job_of(plan, "r1", [], [], {})
    shown = drawn(plan, job, ["table2"], {"r3": [1.0, 2.0]})
    assert [r[-1] for r in shown["rects"]] == ["table1 corridor"]  # table2 is done
    x, y, yaw, length, width = shown["rects"][0][:5]
    # from table1's east end (-1.2) to the west wall (-3.5), the table's width and a robot each side
    assert (x, y, abs(yaw), length, width) == (-2.35, 0.0, pytest.approx(math.pi, abs=1e-4), 2.3, 1.5)
    assert shown["points"] == [[1.0, 2.0, "r3"], [-1.6, 0.0, "table1?"]]
