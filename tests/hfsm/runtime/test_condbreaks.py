"""Breakpoints on a condition over `vars` and `in` (`--break cond:EXPR[@AGENT]`): compiled when the
run is loaded (a bad one is exit 2 at its column), tried at the end of every tick for each agent,
pausing the run at the start of the next tick when the condition turns true (edge, not level). The
pause is an `operator` record, so a run replays byte for byte from its trace without the flag."""

from __future__ import annotations

import json
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import pytest
from helpers import ListTrace
from hypothesis import given, settings
from hypothesis import strategies as st

from hfsm.autonomy import Decision
from hfsm.cli.run import main
from hfsm.load import load
from hfsm.registry import Registry
from hfsm.runtime.breaks import BreakError, condition_names, parse
from hfsm.runtime.program import Program
from hfsm.runtime.run import RunOptions, run
from hfsm.world import InputSpec, NullWorld

COUNT = """\
doc: Counts to 5, a tenth of a second apart.
outcomes: [done]
vars: {n: 0}
outputs: {n: "${vars.n}"}
states:
  count:
    do: set
    with: {n: "${vars.n + 1}"}
    on: {done: rest}
  rest:
    choose:
      - if: "vars.n >= 5"
        then: done
      - else: pause
  pause:
    do: wait
    with: {seconds: 0.1}
    on: {done: count}
"""

OUTER = """\
doc: Calls the counter; its own var is not the counter's.
outcomes: [done]
vars: {m: 7}
states:
  run:
    do: count
    on: {done: done}
"""


def write(folder: Path, name: str, text: str) -> Path:
    path = folder / f"{name}.yaml"
    path.write_text(text)
    return path


def hfsm_run(
    capsys: pytest.CaptureFixture[str], folder: Path, *args: str, script: list[dict[str, Any]] | None = None,
    trace: str = "trace.jsonl", top: str = "count",
) -> tuple[int, dict[str, Any], list[dict[str, Any]], str]:
    write(folder, "count", COUNT)
    write(folder, "outer", OUTER)
    argv = [str(folder / f"{top}.yaml"), "--world", "none", "--json", "--quiet", "--trace", str(folder / trace)]
    if script is not None:
        (folder / "ops.json").write_text(json.dumps(script))
        argv += ["--operator", str(folder / "ops.json")]
    code = main([*argv, *args])
    out, err = capsys.readouterr()
    path = folder / trace
    records = [json.loads(line) for line in path.read_text().splitlines()] if path.exists() else []
    return code, json.loads(out) if out.strip() else {}, records, err


def operators(records: list[dict[str, Any]]) -> list[tuple[float, str, str | None]]:
    return [(r["t"], r["do"], r.get("break")) for r in records if r["kind"] == "operator"]


def test_a_condition_pauses_the_run_at_the_start_of_the_tick_after_it_turned_true(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    code, result, records, _ = hfsm_run(capsys, tmp_path, "--break", "cond:vars.n == 3")
    assert code == 1 and result["error"].startswith("blocked forever: paused at t=0.25 s")
    third = next(r for r in records if r.get("vars") == {"n": 3})
    assert third["t"] == 0.2  # n is 1 at 0 s, 2 at 0.1 s, 3 at 0.2 s
    assert operators(records) == [(0.25, "pause", "cond:vars.n == 3")]


def test_edge_not_level_and_the_run_replays_byte_for_byte_without_the_flag(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    script = [{"t": 0.25, "do": "resume"}]
    code, result, records, _ = hfsm_run(capsys, tmp_path, "--break", "cond:vars.n >= 3", script=script)
    assert (code, result["outputs"]) == (0, {"n": 5})  # n stays >= 3 for 3 more ticks: no more pauses
    assert operators(records) == [(0.25, "pause", "cond:vars.n >= 3"), (0.25, "resume", None)]
    code, _, _, _ = hfsm_run(capsys, tmp_path, "--operator", str(tmp_path / "trace.jsonl"), trace="again.jsonl")
    assert code == 0
    assert (tmp_path / "again.jsonl").read_bytes() == (tmp_path / "trace.jsonl").read_bytes()


def test_a_condition_turning_true_again_pauses_again(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    script = [{"t": 0.05, "do": "resume"}, {"t": 0.15, "do": "resume"}, {"t": 0.25, "do": "resume"}]
    code, _, records, _ = hfsm_run(capsys, tmp_path, "--break", "cond:vars.n % 2 == 1 and vars.n < 5", script=script)
    assert code == 0
    assert [t for t, do, _ in operators(records) if do == "pause"] == [0.05, 0.25]  # n = 1, then n = 3


def test_the_vars_of_a_called_machine_and_only_the_named_agent(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    code, _, records, _ = hfsm_run(
        capsys, tmp_path, "--agents", "a,b", "--break", "cond:vars.n == 2 and vars.m == 7@b", top="outer"
    )
    assert code == 1
    assert operators(records) == [(0.15, "pause", "cond:vars.n == 2 and vars.m == 7@b")]
    code, _, records, _ = hfsm_run(capsys, tmp_path, "--agents", "a,b", "--break", "cond:vars.n == 2@c", top="outer")
    assert code == 0 and operators(records) == []  # no agent c: never true


def test_bad_conditions_are_exit_2_at_their_columns_all_at_once(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    code, _, records, err = hfsm_run(
        capsys, tmp_path, "--break", "cond:vars.nn > 1", "--break", "cond:in.battery < 0.2",
        "--break", "cond:vars.n >", "--break", "cond:state.time > 1",
    )
    assert code == 2 and records == [] and "Traceback" not in err
    assert "--break:1:6: error[E314]: unknown variable 'nn'; did you mean 'n'?" in err
    assert "--break:1:6: error[E330]: unknown input 'in.battery' (the world declares none)" in err
    assert "--break:1:14: error[E314]: bad expression 'vars.n >'" in err
    assert "--break:1:6: error[E331]: 'state.time' cannot be read here" in err


def test_an_expression_with_an_at_sign_keeps_it() -> None:
    names = condition_names([], ())
    point = parse("cond:'a@b' == 'a@b'", names)
    assert (point.pattern, point.agent, point.text) == ("'a@b' == 'a@b'", None, "cond:'a@b' == 'a@b'")
    with pytest.raises(BreakError, match="write cond:EXPR"):
        parse("cond:@r1", names)


class Ticking(NullWorld):
    """Declares `tick`: the tick asked for."""

    def inputs(self) -> Mapping[str, InputSpec]:
        return {"tick": InputSpec("tick", "int", "the tick")}

    def read_input(self, agent: str, name: str, tick: int) -> Any:
        return tick


class Counting(Ticking):
    """Ticking, counting every read the world is asked for."""

    def __init__(self) -> None:
        super().__init__()
        self.reads = 0

    def read_input(self, agent: str, name: str, tick: int) -> Any:
        self.reads += 1
        return tick


LOOK = (COUNT.replace("doc: Counts to 5, a tenth of a second apart.", "doc: Counts to 5, reading in.tick at each count.")
        .replace("vars: {n: 0}", "vars: {n: 0, seen: 0}")
        .replace('with: {n: "${vars.n + 1}"}', 'with: {n: "${vars.n + 1}", seen: "${in.tick}"}'))


def _run_in(tmp_path: Path, spec: str | None, world: NullWorld, decisions: list[Decision],
            source: str = COUNT) -> list[dict[str, Any]]:
    path = write(tmp_path, "count", source)
    loaded = load([path], registry=Registry())
    names = condition_names([m.model for m in loaded.machines.values()], world.inputs())
    points = [] if spec is None else [parse(spec, names)]
    trace = ListTrace()
    options = RunOptions("count", ["robot"], {}, breaks=points, decisions=decisions)
    run(Program(loaded.machines, Registry(), 0.05), world, options, trace)
    return trace.records


def test_a_condition_over_an_input_sees_what_the_machines_read(tmp_path: Path) -> None:
    # the machine reads in.tick at each count: ticks 0, 2, 4 (a static world runs only those)
    records = _run_in(tmp_path, "cond:in.tick >= 3", Ticking(), [Decision(0.25, "resume")], LOOK)
    assert operators(records) == [(0.25, "pause", "cond:in.tick >= 3"), (0.25, "resume", None)]


def test_a_condition_never_asks_the_world(tmp_path: Path) -> None:
    """A world's read can draw from its random streams: a condition that read inputs itself would
    make the run differ from the same run without it, and from its replay."""
    unread, plain = Counting(), Counting()
    records = _run_in(tmp_path, "cond:in.tick >= 0", unread, [])  # COUNT reads no input
    assert operators(records) == [] and unread.reads == 0
    watched = Counting()
    without = _run_in(tmp_path, None, plain, [], LOOK)
    with_it = _run_in(tmp_path, "cond:in.tick > 100", watched, [], LOOK)
    assert watched.reads == plain.reads == 5 and with_it[1:] == without[1:]  # [0]: the run's flags


@settings(max_examples=10, deadline=None)
@given(st.integers(min_value=1, max_value=4))  # at 5 the agent ends in that tick: it is no longer tried
def test_vars_n_equal_k_pauses_just_after_the_tick_it_became_k(k: int) -> None:
    import tempfile

    with tempfile.TemporaryDirectory() as folder:
        records = _run_in(Path(folder), f"cond:vars.n == {k}", NullWorld(), [])
    assert operators(records) == [(round((k - 1) * 0.1 + 0.05, 9), "pause", f"cond:vars.n == {k}")]

