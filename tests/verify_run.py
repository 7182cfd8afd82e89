"""Running hfsm-verify in process, and a counterexample's replay."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from hfsm.cli import run as run_cli
from hfsm.cli import verify as verify_cli

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
