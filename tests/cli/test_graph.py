"""`hfsm-graph` end to end, in process: files written, formats, --depth, --trace, bad input."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from hfsm.cli.graph import main

DATA = Path(__file__).resolve().parents[1] / "diagram" / "data"
ROOT = Path(__file__).resolve().parents[2]


def test_a_folder_gives_a_figure_per_machine_the_call_graph_and_the_legend(tmp_path: Path) -> None:
    assert main([str(DATA), "-o", str(tmp_path), "--format", "svg,dot"]) == 0
    stems = {"lift", "move_table", "relay", "search", "call-graph", "legend"}
    assert {p.name for p in tmp_path.iterdir()} == {f"{s}.{f}" for s in stems for f in ("svg", "dot")}
    assert 'href="lift.svg"' in (tmp_path / "move_table.dot").read_text()


def test_one_file_draws_only_that_machine(tmp_path: Path) -> None:
    code = main(
        [str(DATA / "relay.yaml"), "-o", str(tmp_path), "--format", "png", "--no-legend", "--no-overview"]
    )
    assert code == 0
    assert [p.name for p in tmp_path.iterdir()] == ["relay.png"]
    assert (tmp_path / "relay.png").read_bytes().startswith(b"\x89PNG")


def test_depth_and_pdf(tmp_path: Path) -> None:
    assert main([str(DATA / "relay.yaml"), "-o", str(tmp_path), "--format", "dot,pdf", "--depth", "2"]) == 0
    assert "cluster_move/lift" in (tmp_path / "relay.dot").read_text()
    assert (tmp_path / "relay.pdf").read_bytes().startswith(b"%PDF")
    assert 'href="move_table.pdf"' not in (tmp_path / "relay.dot").read_text()  # not drawn: no link


def test_trace_overlay(tmp_path: Path) -> None:
    trace = tmp_path / "run.jsonl"
    hfsm_run = Path(sys.executable).parent / "hfsm-run"
    run = [str(hfsm_run), str(DATA / "move_table.yaml"), "--agents", "a,b", "--trace", str(trace), "--quiet"]
    subprocess.run(run, check=True, capture_output=True)
    out = tmp_path / "figs"
    assert (
        main([str(DATA / "move_table.yaml"), "-o", str(out), "--format", "dot", "--trace", str(trace)]) == 0
    )
    dot = (out / "move_table.dot").read_text()
    assert "a: ended in &#x27;at_wall&#x27; at t = 3.15 s" in dot
    assert 'label="else \u00d74"' in dot


def test_the_same_files_give_the_same_bytes(tmp_path: Path) -> None:
    for out in ("one", "two"):
        assert main([str(DATA), "-o", str(tmp_path / out), "--format", "dot"]) == 0
    for path in (tmp_path / "one").iterdir():
        assert path.read_bytes() == (tmp_path / "two" / path.name).read_bytes()


def test_an_empty_folder_draws_the_legend_only(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    empty = tmp_path / "empty"
    empty.mkdir()
    assert main([str(empty), "-o", str(tmp_path / "out"), "--format", "dot"]) == 0
    assert [p.name for p in (tmp_path / "out").iterdir()] == ["legend.dot"]
    assert "no machine files" in capsys.readouterr().err


def test_bad_machines_print_every_finding_and_write_nothing(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    bad = tmp_path / "bad.yaml"
    bad.write_text("outcomes: [a]\nstates:\n  s: {do: wiat, on: {done: a}}\n  t: {do: wait, on: {dnoe: a}}\n")
    out = tmp_path / "out"
    assert main([str(bad), str(DATA / "lift.yaml"), "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert "bad.yaml:3:11: error[E300]: unknown behaviour 'wiat'; did you mean 'wait'?" in err
    assert err.count("error[") >= 2
    assert "Traceback" not in err
    assert not out.exists()


def test_bad_arguments_exit_2(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main([str(tmp_path / "missing.yaml"), "-o", str(tmp_path / "o")]) == 2
    assert "no such file or folder" in capsys.readouterr().err
    bad_trace = tmp_path / "t.jsonl"
    bad_trace.write_text("not json\n")
    assert main([str(DATA / "lift.yaml"), "-o", str(tmp_path / "o"), "--trace", str(bad_trace)]) == 2
    assert "t.jsonl:1:1: not a trace record: Expecting value" in capsys.readouterr().err
    bad_trace.write_text('[1, 2]\n{"t": "x", "agent": "a", "path": [], "kind": "enter"}\n')
    assert main([str(DATA / "lift.yaml"), "-o", str(tmp_path / "o"), "--trace", str(bad_trace)]) == 2
    assert "t.jsonl:1:1: not a trace record" in capsys.readouterr().err
    assert main([str(DATA / "lift.yaml"), "-o", str(tmp_path / "o"), "--trace", str(tmp_path / "none")]) == 2
    assert not (tmp_path / "o").exists()
    for args in (["--format", "gif"], ["--depth", "-1"]):
        with pytest.raises(SystemExit) as exc:
            main([str(DATA), *args])
        assert exc.value.code == 2


def test_the_console_script_is_installed() -> None:
    script = Path(sys.executable).parent / "hfsm-graph"
    done = subprocess.run([str(script), "--help"], capture_output=True, text=True, check=False)
    assert done.returncode == 0 and "--depth" in done.stdout


def test_prune_removes_figures_of_machines_that_are_gone(tmp_path: Path) -> None:
    (tmp_path / "old.svg").write_text("<svg/>")
    (tmp_path / "keep.txt").write_text("x")
    assert main([str(DATA / "lift.yaml"), "-o", str(tmp_path), "--prune", "--no-legend", "--no-overview"]) == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["keep.txt", "lift.svg"]


def test_a_machine_by_name_and_a_misspelt_one(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["leader", "-o", str(tmp_path), "--format", "dot", "--no-legend", "--no-overview"]) == 0
    assert (tmp_path / "leader.dot").is_file()
    assert main(["leadr", "-o", str(tmp_path)]) == 2
    assert "did you mean 'leader'?" in capsys.readouterr().err
