"""Parallel states (docs/REFERENCE.md#parallel-states), with exact ticks (dt 0.05)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

from helpers import execute

Machine = Callable[[str, str], Path]

STAND_INS = {
    "exploration": """
        params:
          speed: {type: float}
          ends: {type: str, default: finished}
          after: {type: float, default: 2.0}
        outcomes: [finished, failed]
        states:
          go: {do: wait, with: {seconds: "${params.after}"}, on: {done: pick}}
          pick:
            choose:
              - if: "params.ends == 'finished'"
                then: finished
              - else: failed
    """,
    "detect_victim": """
        params:
          found: {type: bool, default: true}
          after: {type: float, default: 0.5}
        outcomes: [found, not_found]
        outputs: {pose: "${[1.0, 2.0]}"}
        states:
          look: {do: wait, with: {seconds: "${params.after}"}, on: {done: pick}}
          pick:
            choose:
              - if: params.found
                then: found
              - else: not_found
    """,
    "track_head": """
        outcomes: [done]
        states:
          turn: {do: wait, on: {done: done}}
    """,
}

SEARCH = """
    vars: {{pose: null}}
    outcomes: [approach_victim, failed, stopped]
    receives: [stop]
    outputs: {{pose: "${{vars.pose}}"}}
    states:
      search:
        parallel:
          explore: {{do: exploration, with: {{speed: 2.0{explore}}}}}
          detect:  {{do: detect_victim, save: {{pose: pose}}{detect}}}
          head:    {{do: track_head, background: true}}
        join:
          - when: {{detect: found}}
            then: approach_victim
          - when: {{explore: [finished, failed], detect: not_found}}
            then: failed
          - else: failed
        timer: 300
        on: {{timeout: failed, stop: stopped}}
"""


def search(machine: Machine, explore: str = "", detect: str = "") -> Path:
    for name, text in STAND_INS.items():
        machine(name, text)
    return machine("top", SEARCH.format(explore=explore, detect=detect))


def kinds(records: list[dict[str, Any]], kind: str) -> list[dict[str, Any]]:
    return [r for r in records if r["kind"] == kind]


def paths(records: list[dict[str, Any]], kind: str) -> list[str]:
    return ["/".join(r["path"]) for r in kinds(records, kind)]


def test_spec_example_first_rule_wins_and_the_rest_is_cancelled(machine: Machine) -> None:
    result, records = execute(search(machine))
    robot = result.agents["robot"]
    assert (robot.outcome, robot.outputs, robot.time) == ("approach_victim", {"pose": [1.0, 2.0]}, 0.5)
    assert paths(records, "enter") == [
        "top", "top/search", "top/search/explore", "top/search/explore/go", "top/search/detect",
        "top/search/detect/look", "top/search/head", "top/search/head/turn", "top/search/detect/pick",
    ]  # fmt: skip
    # the region that ended, then the still-running ones cancelled last-started first, then the state
    assert paths(records, "exit") == [
        "top/search/detect/look", "top/search/detect/pick", "top/search/detect", "top/search/head/turn",
        "top/search/head", "top/search/explore/go", "top/search/explore", "top/search", "top",
    ]  # fmt: skip
    join = [r for r in kinds(records, "event") if r["path"] == ["top", "search"]]
    assert join == [
        {"t": 0.5, "agent": "robot", "path": ["top", "search"], "kind": "event", "event": "detect=found",
         "target": "approach_victim", "vars": {"pose": [1.0, 2.0]}}  # the region's save, shown on change
    ]  # fmt: skip


def test_the_join_waits_for_every_region_a_rule_names(machine: Machine) -> None:
    result, _ = execute(search(machine, explore=", after: 1.2", detect=", with: {found: false}"))
    assert (result.agents["robot"].outcome, result.time) == ("failed", 1.2)


def test_else_holds_once_every_awaited_region_ended(machine: Machine) -> None:
    for name, text in STAND_INS.items():
        machine(name, text)
    path = machine(
        "top",
        """
        outcomes: [both, other]
        states:
          s:
            parallel:
              a: {do: detect_victim, with: {found: false, after: 0.3}}
              b: {do: detect_victim, with: {found: true, after: 0.1}}
            join:
              - when: {a: found, b: found}
                then: both
              - else: other
    """,
    )
    result, _ = execute(path)
    assert (result.agents["robot"].outcome, result.time) == ("other", 0.3)


def test_regions_that_end_at_entry_save_before_the_next_starts(machine: Machine) -> None:
    path = machine(
        "top",
        """
        vars: {x: 0, y: 0}
        outcomes: [done]
        outputs: {y: "${vars.y}"}
        states:
          s:
            parallel:
              first: {do: set, with: {x: 0.25}}
              second: {do: wait, with: {seconds: "${vars.x}"}}
              third: {do: set, with: {y: "${vars.x * 2}"}}
            join:
              - when: {first: done, second: done, third: done}
                then: done
    """,
    )
    result, _ = execute(path)
    assert (result.agents["robot"].outputs, result.time) == ({"y": 0.5}, 0.25)


def test_all_regions_ending_at_entry_join_in_the_tick_of_entry(machine: Machine) -> None:
    path = machine(
        "top",
        """
        outcomes: [done]
        states:
          s:
            parallel:
              a: {do: log, with: {text: a}}
              b: {do: wait, with: {seconds: 0}}
            join:
              - when: {a: done, b: done}
                then: done
    """,
    )
    result, _ = execute(path)
    assert (result.agents["robot"].outcome, result.time) == ("done", 0.0)


def test_the_timer_of_the_parallel_state_cancels_every_region(machine: Machine) -> None:
    result, records = execute(search(machine, explore=", after: 900", detect=", with: {after: 900}"))
    assert (result.agents["robot"].outcome, result.time) == ("failed", 300.0)
    assert kinds(records, "timeout")[0]["path"] == ["top", "search"]


def test_own_arcs_take_a_message_before_any_region(machine: Machine) -> None:
    path = machine(
        "top",
        """
        vars: {got: ""}
        outcomes: [stopped, heard]
        receives: [stop]
        states:
          kick: {do: send, with: {message: stop, to: all}, on: {sent: s}}
          s:
            parallel:
              listen: {do: wait_for, with: {message: stop}}
              idle: {do: wait}
            join:
              - when: {listen: received}
                then: heard
            timer: 1
            on: {stop: stopped, timeout: heard}
    """,
    )
    result, _ = execute(path)
    assert (result.agents["robot"].outcome, result.time) == ("stopped", 0.05)


def test_an_early_message_takes_its_arc_and_no_region_starts(machine: Machine) -> None:
    path = machine(
        "top",
        """
        outcomes: [stopped, done]
        receives: [stop]
        states:
          kick: {do: send, with: {message: stop, to: all}, on: {sent: pause}}
          pause: {do: wait, with: {seconds: 0.1}, on: {done: s}}
          s:
            parallel:
              a: {do: wait, with: {seconds: "${1 / 0}"}}
            join:
              - when: {a: done}
                then: done
            on: {stop: stopped}
    """,
    )
    result, records = execute(path)
    assert (result.agents["robot"].outcome, result.time) == ("stopped", 0.1)
    assert "top/s/a" not in paths(records, "enter")


def test_regions_take_messages_in_order(machine: Machine) -> None:
    path = machine(
        "top",
        """
        vars: {first: "", second: ""}
        outcomes: [done]
        outputs: {first: "${vars.first}", second: "${vars.second}"}
        states:
          kick: {do: send, with: {message: ping, to: all, data: {n: one}}, on: {sent: again}}
          again: {do: send, with: {message: ping, to: all, data: {n: two}}, on: {sent: s}}
          s:
            parallel:
              a: {do: wait_for, with: {message: ping}, save: {first: n}}
              b: {do: wait_for, with: {message: ping}, save: {second: n}}
            join:
              - when: {a: received, b: received}
                then: done
    """,
    )
    result, _ = execute(path)
    assert (result.agents["robot"].outputs, result.time) == ({"first": "one", "second": "two"}, 0.05)


def test_an_error_in_a_region_cancels_the_others_and_is_the_state_error(machine: Machine) -> None:
    machine(
        "faulty",
        """
        vars: {zero: 0}
        outcomes: [done]
        states:
          pause: {do: wait, with: {seconds: 0.2}, on: {done: divide}}
          divide: {do: wait, with: {seconds: "${1 / vars.zero}"}, on: {done: done}}
    """,
    )
    text = """
        outcomes: [done, broken]
        states:
          s:
            parallel:
              slow: {do: wait, with: {seconds: 5}}
              bad: {do: faulty}
            join:
              - when: {slow: done, bad: done}
                then: done
            %s
    """
    path = machine("top", text % "on: {error: broken}")
    result, records = execute(path)
    assert (result.agents["robot"].outcome, result.time) == ("broken", 0.2)
    assert paths(records, "error") == ["top/s/bad/divide"]
    assert "top/s/slow" in paths(records, "exit")
    path = machine("top2", text % "")
    result, _ = execute(path)
    assert result.error == "top2/s/bad/divide: division by zero in '1 / vars.zero'"


def test_background_regions_are_not_awaited_and_may_end(machine: Machine) -> None:
    path = machine(
        "top",
        """
        vars: {n: 0}
        outcomes: [done]
        outputs: {n: "${vars.n}"}
        states:
          s:
            parallel:
              main: {do: wait, with: {seconds: 0.3}}
              quick: {do: set, with: {n: 7}, background: true}
            join:
              - else: done
    """,
    )
    result, _ = execute(path)
    assert (result.agents["robot"].outputs, result.time) == ({"n": 7}, 0.3)


def test_blocked_forever_names_every_running_region(machine: Machine) -> None:
    path = machine(
        "top",
        """
        outcomes: [done]
        states:
          s:
            parallel:
              a: {do: wait_for, with: {message: never}}
              b: {do: wait}
            join:
              - else: done
    """,
    )
    result, _ = execute(path)
    assert result.error == "blocked forever: robot in top/s/a, top/s/b"


def test_each_entry_restarts_every_region(machine: Machine) -> None:
    path = machine(
        "top",
        """
        vars: {laps: 0}
        outcomes: [done]
        outputs: {laps: "${vars.laps}"}
        states:
          s:
            parallel:
              count: {do: set, with: {laps: "${vars.laps + 1}"}}
              w: {do: wait, with: {seconds: 0.1}}
            join:
              - when: {count: done, w: done}
                then: again
          again:
            choose:
              - if: vars.laps < 3
                then: s
              - else: done
    """,
    )
    result, _ = execute(path)
    assert (result.agents["robot"].outputs, result.time) == ({"laps": 3}, 0.3)
