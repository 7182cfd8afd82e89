"""Compare a run with a case's expectations: each failure says what was expected and what happened."""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from typing import Any

from hfsm.runtime.run import RunResult
from hfsm.testing.model import AgentExpect, Held, InOrderSends, InOrderStates, Sent, TimeRange
from hfsm.testing.plan import CasePlan
from hfsm.testing.standins import Calls
from hfsm.yamlio import Path_

FIELDS = ("failed", "outcome", "time", "outputs", "states", "never", "held", "sends", "calls", "called_with")
SHOWN = 40  # longest list of states or messages shown in a failure


@dataclass(frozen=True, order=True)
class Mismatch:
    file: str  # where the expectation is written
    line: int
    col: int
    message: str

    def format(self) -> str:
        return f"{self.file}:{self.line}:{self.col}: {self.message}"


def show(value: Any) -> str:
    return json.dumps(value, default=str, ensure_ascii=False)


def same(expected: Any, got: Any) -> bool:
    """Equal, numbers to 1e-9 relative: 0.1 + 0.2 is 0.3; true is not 1."""
    if isinstance(expected, bool) or isinstance(got, bool):
        return type(expected) is type(got) and expected == got
    if isinstance(expected, int | float) and isinstance(got, int | float):
        return math.isclose(expected, got, rel_tol=1e-9, abs_tol=1e-12)
    if isinstance(expected, list) and isinstance(got, list):
        return len(expected) == len(got) and all(same(e, g) for e, g in zip(expected, got, strict=True))
    if isinstance(expected, dict) and isinstance(got, dict):
        return expected.keys() == got.keys() and all(same(v, got[k]) for k, v in expected.items())
    return bool(expected == got)


def time_ok(expected: float | TimeRange, got: float) -> bool:
    if isinstance(expected, TimeRange):
        return (expected.min is None or got >= expected.min - 1e-9) and (
            expected.max is None or got <= expected.max + 1e-9
        )
    return abs(got - expected) <= 1e-9


def time_text(expected: float | TimeRange) -> str:
    if isinstance(expected, TimeRange):
        low = "" if expected.min is None else f"{expected.min:g} s <= "
        high = "" if expected.max is None else f" <= {expected.max:g} s"
        return f"{low}t{high}"
    return f"t = {expected:g} s"


class Comparison:
    def __init__(self, plan: CasePlan, result: RunResult, trace: list[dict[str, Any]], calls: Calls) -> None:
        self.plan = plan
        self.result = result
        self.trace = trace
        self.calls = calls
        self.failures: list[Mismatch] = []

    def fail(self, path: Path_, message: str, *, key: bool = False) -> None:
        line, col = self.plan.doc.pos(path, key=key)
        self.failures.append(Mismatch(self.plan.file, line, col, message))

    def run(self) -> list[Mismatch]:
        expect, at = self.plan.expect, self.plan.expect_path
        error = self.result.error
        if expect.error is not None:
            if error is None:
                self.fail(
                    (*at, "error"),
                    f"expected the run to end in an error containing {show(expect.error)}; "
                    "it ended without one",
                )
            elif expect.error not in error:
                self.fail((*at, "error"), f"expected an error containing {show(expect.error)}, got: {error}")
        elif error is not None:
            self.fail(at, f"the run ended in an error: {error}", key=True)
        for agent in self.plan.agents:
            self.agent(agent)
        return sorted(self.failures)

    def agent(self, agent: str) -> None:
        """Each expected field of this agent: its own (under `agents:`), else the one for all."""
        expect, at = self.plan.expect, self.plan.expect_path
        own = expect.agents.get(agent)
        for name in FIELDS:
            source: AgentExpect = expect
            where = at
            if own is not None and name in own.model_fields_set:
                source, where = own, (*at, "agents", agent)
            elif name not in expect.model_fields_set:
                continue
            getattr(self, f"_{name}")(agent, getattr(source, name), (*where, name))

    def _outcome(self, agent: str, expected: str | None, at: Path_) -> None:
        got = self.result.agents[agent]
        if got.outcome != expected:
            ended = f"ended in {show(got.outcome)}" if got.outcome is not None else "did not end"
            self.fail(at, f"{agent}: expected outcome {show(expected)}; it {ended} at t = {got.time:g} s")

    def _failed(self, agent: str, expected: bool | None, at: Path_) -> None:
        got = self.result.agents[agent]
        if expected is not None and (got.failed is not None) != expected:
            happened = f"it failed ({got.failed}) at t = {got.time:g} s" if got.failed else "it did not"
            self.fail(at, f"{agent}: expected {'' if expected else 'not '}to fail; {happened}")

    def _time(self, agent: str, expected: float | TimeRange | None, at: Path_) -> None:
        got = self.result.agents[agent].time
        if expected is not None and not time_ok(expected, got):
            self.fail(at, f"{agent}: expected to end at {time_text(expected)}; it ended at t = {got:g} s")

    def _outputs(self, agent: str, expected: dict[str, Any] | None, at: Path_) -> None:
        got = self.result.agents[agent].outputs
        for name, value in (expected or {}).items():
            if name not in got:
                self.fail(
                    (*at, name),
                    f"{agent}: expected output {name} = {show(value)}; there is none (outputs: {show(got)})",
                )
            elif not same(value, got[name]):
                self.fail(
                    (*at, name), f"{agent}: expected output {name} = {show(value)}, got {show(got[name])}"
                )

    def visited(self, agent: str) -> list[tuple[str, float]]:
        return [
            ("/".join(r["path"][1:]), r["t"])
            for r in self.trace
            if r["kind"] == "enter" and r["agent"] == agent and len(r["path"]) > 1
        ]

    def _states(self, agent: str, expected: list[str] | InOrderStates | None, at: Path_) -> None:
        visited = [path for path, _ in self.visited(agent)]
        if isinstance(expected, InOrderStates):
            missing = _subsequence(expected.in_order, visited, lambda e, g: e == g)
            if missing is not None:
                self.fail(
                    (*at, "in_order", missing),
                    f"{agent}: expected to enter {show(expected.in_order[missing])} after "
                    f"{_after(expected.in_order, missing)}; it entered {_list(visited)}",
                )
            return
        listed = expected or []
        depths = {p.count("/") for p in listed}
        got = [p for p in visited if p.count("/") in depths]
        if got != listed:
            self.fail(at, f"{agent}: expected the states {_list(listed)}; it entered {_list(got)}")

    def _never(self, agent: str, expected: list[str] | None, at: Path_) -> None:
        for i, path in enumerate(expected or []):
            times = [t for p, t in self.visited(agent) if p == path]
            if times:
                self.fail(
                    (*at, i),
                    f"{agent}: expected never to enter {show(path)}; it entered it at t = {times[0]:g} s",
                )

    def _held(self, agent: str, expected: list[Held] | None, at: Path_) -> None:
        got = [r for r in self.trace if r["kind"] == "held" and r["agent"] == agent]
        shown = _list([f"{'/'.join(r['path'][1:])}:{r['event']}@{r['t']:g}" for r in got])
        listed = expected or []
        if len(got) != len(listed):
            self.fail(at, f"{agent}: expected {len(listed)} held arcs; it held {len(got)}: {shown}")
            return
        for i, (want, record) in enumerate(zip(listed, got, strict=True)):
            ok = "/".join(record["path"][1:]) == want.state and record["event"] == want.event
            ok = (
                ok
                and want.level in (None, record["level"])
                and (want.at is None or time_ok(want.at, record["t"]))
            )
            if not ok:
                self.fail(
                    (*at, i),
                    f"{agent}: expected held arc {i + 1} at {want.state}: {want.event}; it held {shown}",
                )

    def sent(self, agent: str) -> list[dict[str, Any]]:
        return [r for r in self.trace if r["kind"] == "send" and r["agent"] == agent]

    def _sends(self, agent: str, expected: list[str | Sent] | InOrderSends | None, at: Path_) -> None:
        sent = self.sent(agent)
        shown = _list([_sent_text(r) for r in sent])
        if isinstance(expected, InOrderSends):
            missing = _subsequence(expected.in_order, sent, _sent_matches)
            if missing is not None:
                wanted = _expected_text(expected.in_order[missing])
                self.fail(
                    (*at, "in_order", missing),
                    f"{agent}: expected to send {wanted} (in this order); it sent {shown}",
                )
            return
        listed = expected or []
        for i, item in enumerate(listed):
            if i >= len(sent) or not _sent_matches(item, sent[i]):
                got = _sent_text(sent[i]) if i < len(sent) else "nothing more"
                self.fail(
                    (*at, i),
                    f"{agent}: expected message {i + 1} sent to be {_expected_text(item)}, got {got}; "
                    f"it sent {shown}",
                )
                return
        if len(sent) > len(listed):
            self.fail(at, f"{agent}: expected {len(listed)} messages sent; it sent {len(sent)}: {shown}")

    def _calls(self, agent: str, expected: dict[str, int] | None, at: Path_) -> None:
        for name, count in (expected or {}).items():
            got = self.calls.count[(agent, name)]
            if got != count:
                self.fail((*at, name), f"{agent}: expected {count} calls of '{name}', got {got}")

    def _called_with(self, agent: str, expected: dict[str, list[dict[str, Any]]] | None, at: Path_) -> None:
        for name, calls in (expected or {}).items():
            got = self.calls.params.get((agent, name), [])
            for i, params in enumerate(calls):
                if i >= len(got):
                    self.fail(
                        (*at, name, i),
                        f"{agent}: expected call {i + 1} of '{name}'; it was called {len(got)} times",
                    )
                    break
                wrong = {k: v for k, v in params.items() if k not in got[i] or not same(v, got[i][k])}
                if wrong:
                    self.fail(
                        (*at, name, i),
                        f"{agent}: expected call {i + 1} of '{name}' with {show(params)}, got {show(got[i])}",
                    )


def _subsequence(expected: list[Any], got: list[Any], match: Any) -> int | None:
    """The index of the first expected item not found, in order, in `got`; None when all are."""
    j = 0
    for i, item in enumerate(expected):
        while j < len(got) and not match(item, got[j]):
            j += 1
        if j == len(got):
            return i
        j += 1
    return None


def _after(expected: list[Any], i: int) -> str:
    return show(expected[i - 1]) if i else "the start"


def _list(items: list[str]) -> str:
    head = items[:SHOWN]
    more = f", … ({len(items) - SHOWN} more)" if len(items) > SHOWN else ""
    return "[" + ", ".join(head) + more + "]"


def _sent_matches(expected: str | Sent, record: dict[str, Any]) -> bool:
    if isinstance(expected, str):
        return bool(record["message"] == expected)
    qualified = f"{expected.scope}/{expected.message}" if expected.scope else expected.message
    if record["message"] != qualified or (expected.to is not None and record["to"] != expected.to):
        return False
    data = record.get("data") or {}
    if expected.data is not None and any(
        k not in data or not same(v, data[k]) for k, v in expected.data.items()
    ):
        return False
    return expected.at is None or time_ok(expected.at, record["t"])


def _sent_text(record: dict[str, Any]) -> str:
    data = f" {show(record['data'])}" if record.get("data") else ""
    return f"{record['message']} to {record['to']}{data} at t = {record['t']:g} s"


def _expected_text(item: str | Sent) -> str:
    if isinstance(item, str):
        return item
    parts = [f"{item.scope}/{item.message}" if item.scope else item.message]
    if item.to is not None:
        parts.append(f"to {item.to}")
    if item.data is not None:
        parts.append(f"with {show(item.data)}")
    if item.at is not None:
        parts.append(f"at {time_text(item.at)}")
    return " ".join(parts)
