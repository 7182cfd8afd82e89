"""Running hfsm-verify in process, and a counterexample's replay."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from hfsm.cli import run as run_cli
from hfsm.cli import verify as verify_cli
from hfsm.verify import search, snapshot
from hfsm.verify.choices import Chooser
from hfsm.verify.step import next_state

DATA = Path(__file__).parent / "verify" / "data"
MACHINES = Path(__file__).parents[1] / "machines"
EXAMPLES = Path(__file__).parents[1] / "examples"


def verify(
    capsys: pytest.CaptureFixture[str], file: Path, *args: str, out: Path
) -> tuple[int, dict[str, Any]]:
    code = verify_cli.main([str(file), *args, "--json", "--out", str(out)])
    captured = capsys.readouterr()
    verdict: dict[str, Any] = json.loads(captured.out) if code in (0, 1) else {"stderr": captured.err}
    verdict["stderr"] = captured.err
    return code, verdict


def replay(file: Path, counterexample: Path, trace: Path) -> int:
    return run_cli.main(
        [str(file), "--world", "none", "--replay", str(counterexample), "--trace", str(trace), "--quiet"]
    )


def prefixes(found: Any, data: bytes) -> list[tuple[int, ...]]:
    """Every run of one state's tick (`data`, as `found.snaps` dumps it): the choices' prefixes."""
    chooser: Chooser = found.chooser
    done: list[tuple[int, ...]] = []
    pending: list[tuple[int, ...]] = [()]
    while pending:
        prefix = pending.pop()
        chooser.begin(prefix)
        engine = found.snaps.load(data)
        next_state(engine, engine.world, chooser, 10**9)
        pending.extend(chooser.siblings())
        done.append(prefix)
    return done


class NoCapture:
    """A stand-in for pytest's capsys where a search runs outside a test's own capture (a fixture)."""

    def readouterr(self) -> Any:
        class Out:
            out = '{"verdict": "ok"}'
            err = ""

        return Out()


def reached_states(
    runs: list[tuple[Path, list[str]]], folder: Path, *, each: int, max_states: int
) -> list[tuple[bytes, Any]]:
    """States searches reach (as their copies' bytes, at most `each` a search, none ended), each with
    the search that made it (kept open, so that its copies still load)."""
    found: list[tuple[bytes, Any]] = []
    visit = search.Search.visit

    def recording(self: search.Search, engine: Any, ended: Any, parent: int) -> bool:
        if ended is None and engine.running and sum(s is self for _, s in found) < each:
            found.append((self.snaps.dump(engine), self))
        return visit(self, engine, ended, parent)

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(search.Search, "visit", recording)
        patch.setattr(snapshot.Snapshots, "close", lambda self: None)
        for file, args in runs:
            verify(NoCapture(), file, *args, "--max-states", str(max_states), out=folder / "ce.jsonl")  # type: ignore[arg-type]
    return found
