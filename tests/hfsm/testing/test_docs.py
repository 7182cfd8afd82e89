"""The test files shown in docs/TESTING.md and the README pass, and the failure shown is the one got."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from hfsm.cli.test import main

ROOT = Path(__file__).resolve().parents[3]


def blocks(path: Path, kind: str) -> list[str]:
    return re.findall(rf"```{kind}\n(.*?)```", path.read_text(encoding="utf-8"), flags=re.S)


def first_test_file(path: Path) -> str:
    return next(b for b in blocks(path, "yaml") if "\ntests:\n" in b)


@pytest.mark.parametrize("doc", ["docs/TESTING.md", "README.md"])
def test_the_shown_test_file_passes(doc: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "lift.test.yaml"
    path.write_text(first_test_file(ROOT / doc), encoding="utf-8")
    assert main([str(path)]) == 0, capsys.readouterr().out


def test_the_shown_failure_is_what_a_wrong_time_gives(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    doc = ROOT / "docs" / "TESTING.md"
    text = first_test_file(doc)
    assert "      time: 2.05\n" in text
    (tmp_path / "lift.test.yaml").write_text(text.replace("      time: 2.05\n", "      time: 2\n", 1))
    monkeypatch.chdir(tmp_path)
    assert main(["lift.test.yaml"]) == 1
    shown = next(b for b in blocks(doc, "text") if b.startswith("FAIL "))
    assert capsys.readouterr().out == shown
