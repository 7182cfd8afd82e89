"""The monitor benchmark's synthetic feed looks like a 16-robot run's trace (the page reads it as one)
and its chattering team runs in world none."""

from __future__ import annotations

from pathlib import Path

from helpers import load_tool

from hfsm.cli.run import main as run_main


def test_the_feed_is_a_16_robot_run_at_its_rate() -> None:
    bench = load_tool("bench_monitor")
    records = bench.records(int(bench.ROBOTS * bench.PER_ROBOT * 10))  # ten simulated seconds
    agents = {r["agent"] for r in records if r["kind"] != "pose"}
    assert agents == {f"r{i}" for i in range(16)}
    assert 20 <= sum(r["kind"] == "pose" for r in records) <= 21  # two a second
    assert records[-1]["t"] < 10.0
    assert all(isinstance(r["path"], list) and isinstance(r["t"], float | int) for r in records)


def test_the_chattering_team_runs_in_world_none(tmp_path: Path) -> None:
    bench = load_tool("bench_monitor")
    machine = tmp_path / "chatter.yaml"
    machine.write_text(bench.CHATTER)
    agents = ",".join(f"r{i}" for i in range(16))
    assert run_main([str(machine), "--world", "none", "--agents", agents, "--quiet", "--param", "rounds=5"]) == 0
