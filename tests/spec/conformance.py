"""Run SPEC example files through `hfsm-run` as the conformance set does: `--json`, `--trace`, `--check`."""

from __future__ import annotations

import json
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from hfsm.cli.run import main

CASES = Path(__file__).resolve().parent / "cases"


@dataclass
class Ran:
    code: int
    result: dict[str, Any]
    records: list[dict[str, Any]]
    err: str

    def events(self, agent: str, *kinds: str) -> list[tuple[float, str, str]]:
        """(t, path below the top, kind or event) of one agent's records of these kinds."""
        return [
            (r["t"], "/".join(r["path"][1:]), r.get("event", r["kind"]))
            for r in self.records
            if r["agent"] == agent and r["kind"] in kinds
        ]


def hfsm_run(capsys: pytest.CaptureFixture[str], tmp: Path, name: str, args: Sequence[str] = ()) -> Ran:
    trace = tmp / f"{name}.jsonl"
    argv = [str(CASES / f"{name}.yaml"), "--world", "none", "--json", "--quiet", "--trace", str(trace), *args]
    code = main(argv)
    out, err = capsys.readouterr()
    records = [json.loads(line) for line in trace.read_text().splitlines()] if trace.exists() else []
    return Ran(code, json.loads(out) if out.strip() else {}, records, err)


def paired(records: list[dict[str, Any]]) -> bool:
    """Every `enter` has its `exit`, nested: a path exits after everything entered below it."""
    opened: dict[str, list[tuple[str, ...]]] = {}
    for record in records:
        stack = opened.setdefault(record["agent"], [])
        path = tuple(record["path"])
        if record["kind"] == "enter":
            stack.append(path)
        elif record["kind"] == "exit":
            if path not in stack or any(p[: len(path)] == path and p != path for p in stack):
                return False
            stack.remove(path)
    return all(not stack for stack in opened.values())
