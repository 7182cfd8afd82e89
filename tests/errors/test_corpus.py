"""A corpus of bad machine files, each with the exact text `hfsm-run --check` prints for it: every
finding's line (`FILE:LINE:COL: severity[CODE]: message`), then the source line with a caret under
what it points at. The expected texts were read and reviewed for wording; to add a file, write
`NAME.yaml` and its `NAME.expected` (stderr of `hfsm-run NAME.yaml --check --world none --lib lib`
run in this folder, with NO_COLOR=1)."""

from __future__ import annotations

import io
import re
from pathlib import Path

import pytest
from helpers import SNIPPET, finding_lines

from hfsm.cli import snippet
from hfsm.cli.run import main
from hfsm.errors import Finding, Severity

HERE = Path(__file__).resolve().parent
CORPUS = HERE / "corpus"
RUN = HERE / "run"
FILES = sorted(p.stem for p in CORPUS.glob("*.yaml"))
FINDING = re.compile(r"^(\S+):(\d+):(\d+): (error|warning)(\[[EW]\d+\])?: \S")


def check(name: str, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch) -> tuple[int, str]:
    monkeypatch.chdir(CORPUS)
    monkeypatch.setenv("NO_COLOR", "1")
    code = main([f"{name}.yaml", "--check", "--world", "none", "--lib", "lib"])
    return code, capsys.readouterr().err


def test_the_corpus_has_at_least_sixty_files_each_with_its_expected_text() -> None:
    assert len(FILES) >= 60
    assert sorted(p.stem for p in CORPUS.glob("*.expected")) == FILES


@pytest.mark.parametrize("name", FILES)
def test_a_bad_file_prints_exactly_its_expected_text(
    name: str, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    code, err = check(name, capsys, monkeypatch)
    expected = (CORPUS / f"{name}.expected").read_text(encoding="utf-8")
    assert err == expected
    errors = [line for line in finding_lines(err) if ": error" in line]
    assert code == (2 if errors else 0) and "Traceback" not in err


@pytest.mark.parametrize("name", FILES)
def test_each_finding_is_followed_by_its_source_line_and_a_caret_at_its_column(name: str) -> None:
    lines = (CORPUS / f"{name}.expected").read_text(encoding="utf-8").splitlines()
    for i, line in enumerate(lines):
        found = FINDING.match(line)
        if found is None:
            assert SNIPPET.match(line) or line.endswith("machines checked)"), line
            continue
        file, number, col = found.group(1), int(found.group(2)), int(found.group(3))
        source = (CORPUS / file).read_text(encoding="utf-8").splitlines()[number - 1]
        assert lines[i + 2] == f"{number} | {source.replace(chr(9), snippet.TAB)}".rstrip()
        carets = lines[i + 3].split("| ", 1)[1]
        assert carets.lstrip(" ").startswith("^")
        assert len(carets) - len(carets.lstrip(" ")) == len(source[: col - 1].replace("\t", snippet.TAB))


def test_a_run_time_error_names_the_file_line_and_column_the_agent_and_the_time(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(RUN)
    assert main(["expression_error.yaml", "--world", "none", "--quiet"]) == 1
    assert capsys.readouterr().err.splitlines() == [
        "expression_error.yaml:10:13: error: robot at t=0.1 s: expression_error/divide: in '1 / vars.zero > 1': "
        "division by zero in '1 / vars.zero'",
        "   |",
        "10 |       - if: 1 / vars.zero > 1",
        "   |             ^^^^^^^^^^^^^^^^^",
    ]
    assert main(["index_error.yaml", "--world", "none", "--quiet"]) == 1
    first = capsys.readouterr().err.splitlines()[0]
    assert first.startswith(
        "index_error.yaml:6:22: error: robot at t=0 s: index_error/first: cannot take [5] of list"
    )


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_colour_only_on_a_terminal_and_never_with_no_color(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("NO_COLOR", raising=False)
    assert snippet.use_colour(_Terminal()) and not snippet.use_colour(io.StringIO())
    monkeypatch.setenv("NO_COLOR", "1")
    assert not snippet.use_colour(_Terminal())
    finding = Finding("m.yaml", 1, 5, "E300", "unknown behaviour 'x'", Severity.ERROR)
    painted = snippet.render(finding, ["do: x"], colour=True)
    assert "\x1b[31m" in painted and "\x1b[0m" in painted
    assert re.sub(r"\x1b\[[0-9;]*m", "", painted) == snippet.render(finding, ["do: x"])


@pytest.mark.parametrize(
    ("line", "col", "pad"),
    [
        ("do: x", 5, 4),
        ("doc: 中文 do: x", 14, 15),  # two characters of two columns each
        ("doc: é do: x", 12, 11),  # é precomposed: one column
        ("doc: e\u0301 do: x", 13, 11),  # e and a combining accent: one column
        ("doc: 😀 do: x", 12, 12),
        ("\tdo: x", 6, 8),  # a tab is shown as four spaces
    ],
)
def test_the_caret_is_under_the_span_in_terminal_columns(line: str, col: int, pad: int) -> None:
    finding = Finding("m.yaml", 1, col, "E300", "unknown behaviour 'x'", Severity.ERROR)
    *_, shown, carets = snippet.render(finding, [line]).splitlines()
    assert carets == "  | " + " " * pad + "^"
    assert shown == "1 | " + line.replace("\t", snippet.TAB)
