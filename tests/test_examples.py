"""Every example runs as its doc says; every machine file in the repository passes the strict checks."""

from __future__ import annotations

from pathlib import Path

import pytest
from helpers import execute

from hfsm.load import load
from hfsm.registry import Registry
from hfsm.runtime.failing import Failure

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"

EXPECTED = {
    "hello": (["robot"], {"robot": ("done", 0.5)}),
    "blink": (["robot"], {"robot": ("timeout", 60.0)}),
    "watchdog": (["robot"], {"robot": ("timeout", 3.0)}),
    "ping_pong": (["a", "b"], {"a": ("lost", 0.2), "b": ("won", 0.15)}),
    "timeouts": (["robot"], {"robot": ("failure", 4.5)}),
    "recover": (["robot"], {"robot": ("failure", 0.0)}),
    "meet": (["a", "b"], {"a": ("lifted", 3.05), "b": ("lifted", 3.05)}),
    "parallel": (["robot"], {"robot": ("found", 1.5)}),
    "watch": (["robot"], {"robot": ("done", 2.0)}),
    "retry": (["robot"], {"robot": ("done", 4.0)}),
    "reach_once": (["robot"], {"robot": ("missed", 1.0)}),
    "fail": (["a", "b", "c"], {"a": ("lifted", 2.55), "b": ("lifted", 2.55), "c": (None, 1.0)}),
}
FAILURES = {"fail": [Failure("c", 1.0)]}  # as its doc says: --fail c@1


def machine_files() -> list[Path]:
    return sorted([*EXAMPLES.glob("*.yaml"), *(ROOT / "machines").glob("*.yaml")])


def test_every_example_has_an_expectation() -> None:
    assert sorted(p.stem for p in EXAMPLES.glob("*.yaml")) == sorted(EXPECTED)


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_example_runs(name: str) -> None:
    agents, expected = EXPECTED[name]
    failures = FAILURES.get(name, [])
    result, records = execute(EXAMPLES / f"{name}.yaml", agents=agents, failures=failures)
    assert result.error is None
    assert {a: (r.outcome, r.time) for a, r in result.agents.items()} == expected
    again = execute(EXAMPLES / f"{name}.yaml", agents=agents, failures=failures)[1]
    assert records == again, "same seed, same trace"


@pytest.mark.parametrize("path", machine_files(), ids=lambda p: f"{p.parent.name}/{p.name}")
def test_machine_passes_strict_checks(path: Path) -> None:
    loaded = load([path], registry=Registry.discover(), strict=True)
    assert loaded.warnings == [] or all(w.severity.value == "error" for w in loaded.warnings)


def test_the_readme_shows_the_parallel_example_as_it_is() -> None:
    readme = (ROOT / "README.md").read_text()
    shown = readme.split("### A parallel state", 1)[1].split("```yaml\n", 1)[1].split("```", 1)[0]
    assert shown in (ROOT / "examples" / "parallel.yaml").read_text()
    assert '{"outcome": "found", "outputs": {"steps": 12}, "time": 1.5}' in readme
