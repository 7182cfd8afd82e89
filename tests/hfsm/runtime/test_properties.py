"""Properties over random valid machines: the interpreter never crashes, every `enter` has its
`exit` (nested: a state exits after everything below it), a machine timer always ends a loop, and a
join with `else` or full coverage never hangs."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import yaml
from helpers import check_nesting, execute
from hypothesis import given
from hypothesis import strategies as st

from hfsm.trace import JsonlTrace, TraceSink, encode

OUTCOMES = ["done", "failure"]
KINDS = ["wait", "wait_forever", "set", "log", "send", "wait_for", "choice", "child", "parallel", "retry"]


@st.composite
def machines(draw: st.DrawFn) -> tuple[dict[str, Any], float | None]:
    n = draw(st.integers(1, 6))
    names = [f"s{i}" for i in range(n)]
    kinds = [draw(st.sampled_from(KINDS)) for _ in names]
    plain = [s for s, k in zip(names, kinds, strict=True) if k != "choice"]
    timer = draw(st.one_of(st.none(), st.sampled_from([0.05, 0.3, 1.0, 2.5])))
    states = {name: _state(draw, kind, names, plain) for name, kind in zip(names, kinds, strict=True)}
    machine: dict[str, Any] = {"vars": {"n": 0}, "outcomes": OUTCOMES, "receives": ["poke"], "states": states}
    if timer is not None:
        machine["timer"] = timer
    if draw(st.booleans()):
        machine["any"] = {"poke": draw(st.sampled_from(names + OUTCOMES))}
    return machine, timer


def _state(draw: st.DrawFn, kind: str, names: list[str], plain: list[str]) -> dict[str, Any]:
    def target(pool: list[str] = names) -> str:
        return str(draw(st.sampled_from(pool + OUTCOMES)))

    if kind == "choice":
        return {
            "choose": [
                {"if": f"vars.n % 3 == {draw(st.integers(0, 2))}", "then": target(plain)},
                {"else": target(plain)},
            ]
        }
    state: dict[str, Any]
    if kind == "wait":
        state = {
            "do": "wait",
            "with": {"seconds": draw(st.sampled_from([0, 0.05, 0.12, 0.5]))},
            "on": {"done": target()},
        }
    elif kind == "wait_forever":
        state = {
            "do": "wait",
            "timer": draw(st.sampled_from([0.1, 0.4])),
            "on": {"done": target(), "timeout": target()},
        }
    elif kind == "set":
        state = {"do": "set", "with": {"n": "${vars.n + 1}"}, "on": {"done": target()}}
    elif kind == "log":
        state = {"do": "log", "with": {"text": "n=${vars.n}"}, "on": {"done": target()}}
    elif kind == "send":
        state = {"do": "send", "with": {"message": "poke"}, "on": {"sent": target()}}
    elif kind == "wait_for":
        state = {
            "do": "wait_for",
            "with": {"message": "poke"},
            "timer": 0.3,
            "on": {"received": target(), "timeout": target()},
        }
    elif kind in ("parallel", "retry"):
        return _v2_state(draw, kind, target)
    else:
        state = {"do": "child", "on": {"finished": target(), "timeout": target()}}
    if draw(st.booleans()):
        state["watch"] = [{"if": f"state.time >= {draw(st.sampled_from([0, 0.1, 0.5]))}", "then": target()}]
    if draw(st.booleans()) and kind not in ("wait_forever", "wait_for", "child"):
        state["on"]["error"] = target()
    return state


def _v2_state(draw: st.DrawFn, kind: str, target: Any) -> dict[str, Any]:
    """A parallel state, or a call of the child machine with a retry (and maybe a watch)."""
    if kind == "parallel":
        return _parallel(draw, target, sorted(REGIONS))
    state: dict[str, Any] = {
        "do": "child",
        "retry": {"on": draw(st.sampled_from([["finished"], ["timeout"], ["error"]])), "times": 2},
        "on": {"finished": target(), "timeout": target()},
    }
    if draw(st.booleans()):
        state["retry"]["delay"] = draw(st.sampled_from([0, 0.05, 0.2]))
    if draw(st.booleans()):
        state["watch"] = [{"if": f"state.time >= {draw(st.sampled_from([0.1, 0.5]))}", "then": target()}]
    return state


REGIONS: dict[str, tuple[dict[str, Any], list[str]]] = {
    "wait": ({"do": "wait", "with": {"seconds": 0.1}}, ["done"]),
    "now": ({"do": "set", "with": {"n": "${vars.n + 1}"}}, ["done"]),
    "child": ({"do": "child"}, ["finished", "timeout"]),
    "listen": ({"do": "wait_for", "with": {"message": "poke"}}, ["received"]),
}


def _parallel(draw: st.DrawFn, target: Any, pool: list[str]) -> dict[str, Any]:
    """A parallel state whose join has `else`, or rules covering every combination of outcomes."""
    kinds = draw(st.lists(st.sampled_from(pool), min_size=1, max_size=3))
    regions = {f"r{i}": dict(REGIONS[k][0]) for i, k in enumerate(kinds)}
    if draw(st.booleans()):
        regions["bg"] = {"do": "wait", "background": True}
    first = "r0"
    join: list[dict[str, Any]] = [
        {"when": {first: outcome}, "then": target()} for outcome in REGIONS[kinds[0]][1]
    ]  # covers every combination: each outcome of the first region has a rule
    if draw(st.booleans()):
        join = [{"when": {first: REGIONS[kinds[0]][1][0]}, "then": target()}, {"else": target()}]
    state: dict[str, Any] = {"parallel": regions, "join": join, "timer": draw(st.sampled_from([0.3, 1.0]))}
    state["on"] = {"timeout": target()}
    return state


CHILD = {
    "outcomes": ["finished"],
    "timer": 0.7,
    "states": {
        "a": {"do": "wait", "with": {"seconds": 0.1}, "on": {"done": "b"}},
        "b": {"do": "wait", "with": {"seconds": 0.2}, "on": {"done": "a"}},
    },
}


def _run(
    tmp_path: Path, machine: dict[str, Any], max_time: float, sink: TraceSink | None = None
) -> tuple[Any, list[dict[str, Any]]]:
    (tmp_path / "child.yaml").write_text(yaml.safe_dump(CHILD))
    (tmp_path / "top.yaml").write_text(yaml.safe_dump(machine, sort_keys=False))
    return execute(tmp_path / "top.yaml", agents=["a", "b"], max_time=max_time, sink=sink)


@given(machines())
def test_never_crashes_and_every_enter_has_its_exit(
    tmp_path_factory: Any, drawn: tuple[dict[str, Any], Any]
) -> None:
    machine, _ = drawn
    result, records = _run(tmp_path_factory.mktemp("m"), machine, max_time=5)
    assert set(result.agents) == {"a", "b"}
    # every wait here has a timer above it (as the checks ask): the run never blocks for good
    assert not (result.error or "").startswith("blocked forever"), result.error
    check_nesting(records)


@given(machines())
def test_the_jsonl_trace_is_the_records_encoded_one_by_one(
    tmp_path_factory: Any, drawn: tuple[dict[str, Any], Any]
) -> None:
    """The JSONL sink gets the hot records as text (hfsm.runtime.records): the same bytes."""
    folder = tmp_path_factory.mktemp("m")
    _, records = _run(folder, drawn[0], max_time=5)
    _run(folder, drawn[0], max_time=5, sink=JsonlTrace(folder / "t.jsonl"))
    assert (folder / "t.jsonl").read_text(encoding="utf-8") == "".join(encode(r) + "\n" for r in records)


@given(machines().filter(lambda drawn: drawn[1] is not None))
def test_a_machine_timer_always_ends_the_run(
    tmp_path_factory: Any, drawn: tuple[dict[str, Any], float]
) -> None:
    machine, timer = drawn
    result, _ = _run(tmp_path_factory.mktemp("m"), machine, max_time=timer + 5)
    if result.error:
        assert "state entries in one tick" in result.error or "division" in result.error, result.error
    else:
        assert all(r.outcome is not None and r.time <= timer + 1e-9 for r in result.agents.values())


@st.composite
def joins(draw: st.DrawFn) -> dict[str, Any]:
    """A top machine with one parallel state of finite regions and a join that is checked complete."""
    state = _parallel(draw, lambda: draw(st.sampled_from(OUTCOMES)), ["child", "now", "wait"])
    state.pop("timer")
    state.pop("on")
    return {"vars": {"n": 0}, "outcomes": OUTCOMES, "receives": ["poke"], "states": {"p": state}}


@given(joins())
def test_a_complete_join_never_hangs(tmp_path_factory: Any, machine: dict[str, Any]) -> None:
    result, records = _run(tmp_path_factory.mktemp("m"), machine, max_time=10)
    assert result.error is None, result.error
    assert all(r.outcome in OUTCOMES for r in result.agents.values())
    check_nesting(records)
