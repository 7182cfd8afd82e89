"""The names of docs/REFERENCE.md#watches and #retries in expressions: `state.*`, `machine.time`, `in.x`."""

from __future__ import annotations

import re
from typing import Any

import pytest

from hfsm.expr import ExprSyntaxError, ExprValueError, Names, Scope, compile_expr, reads


class Live:
    def __init__(self) -> None:
        self.asked: list[str] = []

    def state_time(self) -> float:
        return 0.3

    def state_attempt(self) -> int:
        return 2

    def machine_time(self) -> float:
        return 1.5

    def input(self, name: str) -> Any:
        self.asked.append(name)
        return {"seen": True, "bearing": -0.5, "pose": [1, 2]}[name]


NAMES = Names(params=["x"], vars=["items"])


def ev(text: str, live: Live | None = None) -> Any:
    return compile_expr(text, NAMES)(Scope({"x": 1}, {"items": [True]}, "r1", live or Live()))


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("state.time", 0.3),
        ("state.attempt + 1", 3),
        ("machine.time > state.time", True),
        ("in.seen and in.bearing < 0", True),
        ("in.pose[1]", 2),
        ("in.seen in vars.items", True),
        ("not in.seen", False),
        ("'in.seen'", "in.seen"),
        ("[in.bearing, abs(in.bearing)]", [-0.5, 0.5]),
    ],
)
def test_live_values(text: str, value: Any) -> None:
    assert ev(text) == value


def test_inputs_are_read_only_when_evaluated() -> None:
    live = Live()
    fn = compile_expr("in.seen or in.bearing", NAMES)
    assert live.asked == []
    fn(Scope({}, {}, "r1", live))
    assert live.asked == ["seen"]


@pytest.mark.parametrize(
    ("text", "names", "message"),
    [
        ("state.tim", NAMES, "unknown name 'state.tim'; did you mean 'state.time'?"),
        ("machine.date", NAMES, "unknown name 'machine.date'; only 'machine.time'"),
        ("state.time", Names(["x"], None, state=False), "'state.time' cannot be read here"),
        ("state.attempt", Names(["x"], None, state=False), "'state.attempt' cannot be read here"),
        ("machine.time", Names(["x"], None, machine_time=False), "'machine.time' cannot be read in"),
        ("in.bearng", Names([], [], inputs=["bearing"]), "unknown input 'in.bearng' (the world declares"),
        ("in.x", Names([], [], inputs=[]), "(the world declares none)"),
        ("in.a.b", NAMES, "'in.a.b': no attribute access"),
        ("__in__.x", NAMES, "unknown name '__in__'"),
    ],
)
def test_rejected_where_they_cannot_be_read(text: str, names: Names, message: str) -> None:
    with pytest.raises(ExprSyntaxError, match=re.escape(message)):
        compile_expr(text, names)


def test_did_you_mean_for_inputs() -> None:
    with pytest.raises(ExprSyntaxError, match="did you mean 'bearing'"):
        compile_expr("in.bearng", Names([], [], inputs=["bearing", "seen"]))


def test_without_a_running_state_live_names_are_run_time_errors() -> None:
    with pytest.raises(ExprValueError, match=re.escape("'state.time' cannot be read here")):
        compile_expr("state.time", NAMES)(Scope({}, {}, "r1"))
    with pytest.raises(ExprValueError, match=re.escape("'in.seen' cannot be read here")):
        compile_expr("in.seen", NAMES)(Scope({}, {}, "r1"))


def test_reads_names_what_an_expression_reads() -> None:
    assert reads("in.seen and vars.items[0] or state.time > machine.time") == {
        "in.seen",
        "vars.items",
        "state.time",
        "machine.time",
    }
    assert reads("3 in vars.items") == {"vars.items"}
    assert reads("((") == set()
