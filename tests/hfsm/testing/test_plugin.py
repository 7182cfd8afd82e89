"""The pytest plug-in: a user's plain `pytest` collects `*.test.yaml`, one item a case."""

from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]


def pytest_in(folder: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-q", "-rN", str(folder)],
        cwd=folder,
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )


def test_cases_are_items_and_failures_are_at_their_positions(tmp_path: Path) -> None:
    (tmp_path / "nap.yaml").write_text(
        "outcomes: [done]\nstates:\n  nap: {do: wait, with: {seconds: 2}, on: {done: done}}\n"
    )
    (tmp_path / "nap.test.yaml").write_text(
        textwrap.dedent(
            """\
            machine: nap
            tests:
              two_seconds:
                expect: {outcome: done, time: 2}
              three_seconds:
                expect: {outcome: done, time: 3}
            """
        )
    )
    done = pytest_in(tmp_path)
    assert done.returncode == 1, done.stdout + done.stderr
    assert "nap.test.yaml:6:35: robot: expected to end at t = 3 s; it ended at t = 2 s" in done.stdout
    assert "1 failed, 1 passed" in done.stdout


def test_a_bad_test_file_is_a_collection_error_at_its_position(tmp_path: Path) -> None:
    (tmp_path / "bad.test.yaml").write_text("machine: elect_leadr\ntests:\n  one: {expect: {}}\n")
    done = pytest_in(tmp_path)
    assert done.returncode == 2, done.stdout + done.stderr
    assert "bad.test.yaml:1:10: error[T302]: no machine 'elect_leadr'" in done.stdout
    assert "did you mean 'elect_leader'?" in done.stdout


def test_every_machine_of_the_library_has_a_test_file() -> None:
    machines = sorted(p.stem for p in (ROOT / "machines").glob("*.yaml"))
    tested = sorted(
        p.name.removesuffix(".test.yaml") for p in (ROOT / "tests" / "machines").glob("*.test.yaml")
    )
    assert machines == tested
    for name in tested:
        text = (ROOT / "tests" / "machines" / f"{name}.test.yaml").read_text()
        assert f"\nmachine: {name}\n" in text
