"""Running hfsm-verify in process, and a counterexample's replay."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from hfsm.cli import run as run_cli
from hfsm.cli import verify as verify_cli
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
