"""Every example of docs/REFERENCE.md runs (or is refused) as the page says it does."""

from __future__ import annotations

import io
import json
import re
import shlex
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

import pytest

from hfsm.cli.run import main

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "REFERENCE.md"
BLOCK = re.compile(r"```yaml\n(# (example|file|check): (\S+)(.*?)\n.*?)```", re.S)


def blocks() -> list[tuple[str, str, str, str]]:
    """(kind, file name, the rest of the first line, the YAML) of every YAML block of the page."""
    return [(m.group(2), m.group(3), m.group(4), m.group(1)) for m in BLOCK.finditer(PAGE.read_text())]


def examples() -> list[tuple[str, str]]:
    return [(name, rest) for kind, name, rest, _ in blocks() if kind in ("example", "check")]


@pytest.fixture(scope="module")
def folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("reference")
    for _, name, _, text in blocks():
        (path / name).write_text(text)
    return path


def test_every_yaml_block_is_a_named_file_and_names_are_unique() -> None:
    text = PAGE.read_text()
    assert text.count("```yaml") == len(blocks())
    names = [name for _, name, _, _ in blocks()]
    assert len(names) == len(set(names)) and len(names) >= 14


@pytest.mark.parametrize(("name", "rest"), examples(), ids=[n for n, _ in examples()])
def test_the_example_gives_what_the_page_says(folder: Path, name: str, rest: str) -> None:
    command, gives = rest.split("gives:")
    argv = shlex.split(command.split("run:")[1])
    assert argv[0] == "hfsm-run" and argv[1] == name
    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        code = main([str(folder / name), *argv[2:], "--quiet"])
    gives = gives.strip()
    if gives.startswith("exit"):
        expected_code, finding = (part.strip() for part in gives.removeprefix("exit").split(","))
        assert code == int(expected_code), err.getvalue()
        assert f"[{finding}]" in err.getvalue()
        assert re.match(rf"{re.escape(str(folder / name))}:\d+:\d+: error\[{finding}\]", err.getvalue())
    else:
        assert code == 0, err.getvalue()
        assert json.loads(out.getvalue()) == json.loads(gives)
