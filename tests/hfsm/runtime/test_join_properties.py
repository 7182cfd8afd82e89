"""Properties over random parallel states (docs/REFERENCE.md#parallel-states) with random join rules, `else`, background
regions, regions that retry, nest a parallel state, wait for a message, fail or never end:

- the interpreter never crashes, and every `enter` has its `exit`;
- a parallel state that passes the checks (no error; no W403, an awaited region that can wait
  forever with no timer) never hangs: every agent's run ends, or the state's timer fires.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import yaml
from helpers import check_nesting, execute
from hypothesis import given
from hypothesis import strategies as st

from hfsm.errors import UserError
from hfsm.load import load
from hfsm.registry import Registry

HELPERS: dict[str, dict[str, Any]] = {
    "child": {  # always ends by its timer
        "outcomes": ["finished"],
        "timer": 0.7,
        "states": {
            "a": {"do": "wait", "with": {"seconds": 0.1}, "on": {"done": "b"}},
            "b": {"do": "wait", "with": {"seconds": 0.2}, "on": {"done": "a"}},
        },
    },
    "pick": {
        "params": {"way": {"type": "str"}},
        "outcomes": ["left", "right"],
        "states": {
            "w": {"do": "wait", "with": {"seconds": 0.1}, "on": {"done": "c"}},
            "c": {"choose": [{"if": "params.way == 'left'", "then": "left"}, {"else": "right"}]},
        },
    },
    "twice": {  # retries `pick` until it goes right, or twice
        "outcomes": ["left", "right"],
        "states": {
            "p": {
                "do": "pick",
                "with": {"way": "${'left' if state.attempt < 3 else 'right'}"},
                "retry": {"on": ["left"], "times": 2, "delay": 0.05},
                "on": {"left": "left", "right": "right"},
            }
        },
    },
    "inner": {  # a parallel state inside a region
        "outcomes": ["done", "failure"],
        "states": {
            "q": {
                "parallel": {
                    "a": {"do": "wait", "with": {"seconds": 0.15}},
                    "b": {"do": "pick", "with": {"way": "right"}},
                    "c": {"do": "wait", "background": True},
                },
                "join": [{"when": {"b": "left"}, "then": "failure"}, {"else": "done"}],
            }
        },
    },
    "boom": {
        "vars": {"n": 0},
        "outcomes": ["done"],
        "states": {"s": {"do": "set", "with": {"n": "${1 // vars.n}"}, "on": {"done": "done"}}},
    },
}

# region kind -> (region, outcomes of its behaviour, whether it can wait forever)
KINDS: dict[str, tuple[dict[str, Any], list[str], bool]] = {
    "wait": ({"do": "wait", "with": {"seconds": 0.2}}, ["done"], False),
    "now": ({"do": "set", "with": {"n": "${vars.n + 1}"}}, ["done"], False),
    "poke": ({"do": "send", "with": {"message": "poke", "to": "all"}}, ["sent"], False),
    "child": ({"do": "child"}, ["finished", "timeout"], False),
    "left": ({"do": "pick", "with": {"way": "left"}}, ["left", "right"], False),
    "right": ({"do": "pick", "with": {"way": "right"}}, ["left", "right"], False),
    "twice": ({"do": "twice"}, ["left", "right"], False),
    "inner": ({"do": "inner"}, ["done", "failure"], False),
    "boom": ({"do": "boom"}, ["done"], False),
    "listen": ({"do": "wait_for", "with": {"message": "poke"}}, ["received"], True),
    "forever": ({"do": "wait"}, ["done"], True),
}
TARGETS = ["done", "failure", "again"]


@st.composite
def parallel_machines(draw: st.DrawFn) -> dict[str, Any]:
    kinds = draw(st.lists(st.sampled_from(sorted(KINDS)), min_size=1, max_size=4))
    regions = {f"r{i}": dict(KINDS[k][0]) for i, k in enumerate(kinds)}
    outcomes = {f"r{i}": KINDS[k][1] for i, k in enumerate(kinds)}
    for i in range(draw(st.integers(0, 2))):
        regions[f"bg{i}"] = {**KINDS[draw(st.sampled_from(["forever", "listen", "child", "wait"]))][0]}
        regions[f"bg{i}"]["background"] = True
    join: list[dict[str, Any]] = []
    for _ in range(draw(st.integers(0, 3))):
        named = draw(st.lists(st.sampled_from(sorted(outcomes)), min_size=1, max_size=3, unique=True))
        when = {}
        for r in named:
            chosen = draw(st.lists(st.sampled_from(outcomes[r]), min_size=1, unique=True))
            when[r] = chosen[0] if len(chosen) == 1 else chosen
        join.append({"when": when, "then": draw(st.sampled_from(TARGETS))})
    if not join or draw(st.booleans()):
        join.append({"else": draw(st.sampled_from(TARGETS))})
    state: dict[str, Any] = {"parallel": regions, "join": join}
    on: dict[str, str] = {}
    if draw(st.booleans()):
        state["timer"] = draw(st.sampled_from([0.3, 1.0, 2.0]))
        on["timeout"] = draw(st.sampled_from(TARGETS))
    if draw(st.booleans()):
        on["error"] = draw(st.sampled_from(TARGETS))
    if draw(st.booleans()):
        state["watch"] = [{"if": f"state.time >= {draw(st.sampled_from([0.1, 0.5]))}", "then": "failure"}]
    if on:
        state["on"] = on
    again = {"do": "set", "with": {"n": "${vars.n + 1}"}, "on": {"done": "check"}}
    check = {"choose": [{"if": "vars.n < 3", "then": "p"}, {"else": "done"}]}
    states = {"p": state, "again": again, "check": check}
    return {"vars": {"n": 0}, "outcomes": ["done", "failure"], "states": states}


def _write(folder: Path, machine: dict[str, Any]) -> Path:
    for name, helper in HELPERS.items():
        (folder / f"{name}.yaml").write_text(yaml.safe_dump(helper, sort_keys=False))
    path = folder / "top.yaml"
    path.write_text(yaml.safe_dump(machine, sort_keys=False))
    return path


def _checked(path: Path) -> bool | None:
    """None: the checks refuse it; else whether it passes them with no awaited region unbounded."""
    try:
        loaded = load([path], registry=Registry())
    except UserError:
        return None
    return not any(w.code == "W403" for w in loaded.warnings)


ALLOWED_ERRORS = ("blocked forever", "stopped at --max-time", "division by zero")


@given(parallel_machines())
def test_random_parallel_states_never_crash_and_pair_every_enter(
    tmp_path_factory: Any, machine: dict[str, Any]
) -> None:
    path = _write(tmp_path_factory.mktemp("p"), machine)
    if _checked(path) is None:
        return
    result, records = execute(path, agents=["a", "b"], max_time=20)
    assert set(result.agents) == {"a", "b"}
    assert (
        result.error is None
        or result.error.split(": ")[0] in ALLOWED_ERRORS
        or ("division by zero" in result.error)
    ), result.error
    check_nesting(records)


@given(parallel_machines())
def test_a_checked_join_never_hangs(tmp_path_factory: Any, machine: dict[str, Any]) -> None:
    path = _write(tmp_path_factory.mktemp("p"), machine)
    if not _checked(path):
        return
    result, records = execute(path, agents=["a", "b"], max_time=60)
    if result.error is not None:  # an unmapped error in a region reaches the top: that is no hang
        assert "division by zero" in result.error, result.error
    else:
        assert all(r.outcome in ("done", "failure") for r in result.agents.values()), result.agents
    check_nesting(records)
