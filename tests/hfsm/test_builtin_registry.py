"""Built-ins are declared with their traits in one place (hfsm/builtins/): a new blocking built-in is one
module plus its registration, and nothing outside the registry compares a callee with a built-in's name."""

from __future__ import annotations

import ast
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from helpers import execute, hfsm_run, write

from hfsm.builtins import BUILTINS, REGISTRY, Builtin, register, unregister
from hfsm.builtins.registry import Literals
from hfsm.diagram.dot import to_dot
from hfsm.diagram.extract import Sources, machine_figure
from hfsm.diagram.model import nodes
from hfsm.load import load
from hfsm.registry import Registry
from hfsm.runtime.agent import Agent, Event, Frame, Region
from hfsm.runtime.host import Host
from hfsm.spec import BehaviourSpec, ParamSpec

ROOT = Path(__file__).resolve().parents[2]


# --- a toy blocking built-in, declared and registered here only ------------------------------------


class Latch:
    """Waits until the tick given, then ends `done` with how long it waited."""

    __slots__ = ("deadline", "waited")

    def __init__(self, deadline: int, waited: int) -> None:
        self.deadline: int | None = deadline
        self.waited = waited

    def advance(self, tick: int) -> Event | None:
        assert self.deadline is not None
        return Event("done", {"waited": self.waited}) if tick >= self.deadline else None

    def cancel(self) -> str:
        return ""


def start_latch(
    host: Host, agent: Agent, frame: Frame, params: dict[str, Any], where: Frame | Region
) -> Latch:
    return Latch(host.tick + params["ticks"], params["ticks"])


def latch_blocks(with_: Literals) -> str | None:
    return "'latch'"


LATCH = Builtin(
    BehaviourSpec(
        "latch", "builtin", {"ticks": ParamSpec("ticks", "int")}, ("done",), outputs=frozenset({"waited"})
    ),
    start_latch,
    blocks=latch_blocks,
    role="barrier",
    traced=("waited",),
)

USES_LATCH = """
    outcomes: [done]
    vars: {waited: 0}
    outputs: {waited: "${vars.waited}"}
    states:
      both:
        parallel:
          hold: {do: latch, with: {ticks: 3}}
          pause: {do: wait, with: {seconds: 0.05}}
        join:
          - when: {hold: done, pause: done}
            then: again
      again: {do: latch, with: {ticks: 2}, save: {waited: waited}, on: {done: done}}
"""


@pytest.fixture
def latch() -> Iterator[Builtin]:
    register(LATCH)
    try:
        yield LATCH
    finally:
        unregister(LATCH.name)


def test_a_registered_built_in_runs(latch: Builtin, tmp_path: Path) -> None:
    path = write(tmp_path, "uses_latch", USES_LATCH)
    result, records = execute(path)
    assert result.agents["robot"].outcome == "done"
    assert result.agents["robot"].outputs == {"waited": 2}
    assert result.time == pytest.approx(0.25)  # 3 ticks in the parallel state, then 2
    ended = [r for r in records if r["kind"] == "event" and r["path"][-1] == "again"]
    assert ended and ended[0]["waited"] == 2  # its `traced` output is in the trace


def test_a_registered_built_in_is_checked_by_its_traits(
    latch: Builtin, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = write(tmp_path, "uses_latch", USES_LATCH)
    code, _, err = hfsm_run(capsys, path, "--check", "--world", "none")
    assert code == 0, err
    assert "W403" in err and "region 'hold' can wait forever ('latch')" in err
    bad = write(tmp_path, "bad_latch", USES_LATCH.replace("ticks: 2", "tics: 2"))
    code, _, err = hfsm_run(capsys, bad, "--check", "--world", "none")
    assert code == 2 and "E302" in err and "did you mean 'ticks'" in err


def test_a_registered_built_in_is_drawn_by_its_role(latch: Builtin, tmp_path: Path) -> None:
    path = write(tmp_path, "uses_latch", USES_LATCH)
    registry = Registry()
    figure = machine_figure("uses_latch", Sources.from_loaded(load([path], registry=registry), registry))
    roles = {n.id: n.role for n in nodes(figure)}
    assert roles["again"] == "barrier"
    assert "again" in to_dot(figure)


def test_unregistered_it_is_unknown_again(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert "latch" not in REGISTRY and "latch" not in BUILTINS
    path = write(tmp_path, "uses_latch", USES_LATCH)
    code, _, err = hfsm_run(capsys, path, "--check", "--world", "none")
    assert code == 2 and "latch" in err


def test_a_name_is_registered_once() -> None:
    with pytest.raises(ValueError, match="registered twice"):
        register(REGISTRY["wait"])


# --- no comparison of a callee with a built-in's name outside the registry --------------------------

CALLEE = ("do", "callee", "callee.kind", "spec.name")  # what names a state's callee in the source


def _names(node: ast.expr) -> list[str]:
    """The string constants of a comparison's operand (a constant, or a tuple, list or set of them)."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return [node.value]
    if isinstance(node, ast.Tuple | ast.List | ast.Set):
        return [e.value for e in node.elts if isinstance(e, ast.Constant) and isinstance(e.value, str)]
    return []


def _names_callee(node: ast.expr) -> bool:
    text = ast.unparse(node)
    return any(text == c or text.endswith("." + c) for c in CALLEE)


def name_comparisons(source: str, builtins: set[str]) -> list[tuple[int, str]]:
    """Comparisons of a callee (`do`, `x.do`, `callee.kind`, `spec.name`...) with a built-in's name, and
    module constants holding one."""
    found = []
    tree = ast.parse(source)
    for node in ast.walk(tree):
        if isinstance(node, ast.Compare):
            operands = [node.left, *node.comparators]
            named = [n for o in operands for n in _names(o) if n in builtins]
            if named and any(_names_callee(o) for o in operands):
                found.append((node.lineno, ast.unparse(node)))
    for statement in tree.body if isinstance(tree, ast.Module) else ():
        value = statement.value if isinstance(statement, ast.Assign) else None
        if isinstance(value, ast.Constant) and value.value in builtins:
            found.append((statement.lineno, ast.unparse(statement)))
    return found


def test_the_finder_finds_what_it_looks_for() -> None:
    source = 'if state.do == "barrier": pass\nif spec.name not in ("send", "x"): pass\nBARRIER = "barrier"\n'
    assert [line for line, _ in name_comparisons(source, set(BUILTINS))] == [1, 2, 3]
    others = 'if record["kind"] == "send": pass\nif do == "pause": pass\nKINDS = ("send", "exit")\n'
    assert name_comparisons(others, set(BUILTINS)) == []


def test_no_callee_is_compared_with_a_built_in_name_outside_the_registry() -> None:
    builtins = set(BUILTINS)
    found = []
    for path in sorted((ROOT / "hfsm").rglob("*.py")):
        if "builtins" in path.relative_to(ROOT).parts:
            continue
        for line, text in name_comparisons(path.read_text(encoding="utf-8"), builtins):
            found.append(f"{path.relative_to(ROOT)}:{line}: {text}")
    assert found == []
