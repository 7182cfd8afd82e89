"""`hfsm-run --list`, docs/BEHAVIOURS.md, and the README's primitive (issue 12.2)."""

from __future__ import annotations

import re
from collections.abc import Callable
from pathlib import Path

import pytest

from hfsm.builtins import BUILTINS
from hfsm.cli.run import main
from hfsm_behaviours.registry import primitives

ROOT = Path(__file__).resolve().parents[2]


def listing(capsys: pytest.CaptureFixture[str], *argv: str) -> str:
    assert main(["--list", *argv]) == 0
    return capsys.readouterr().out


def test_docs_behaviours_is_the_listing(capsys: pytest.CaptureFixture[str]) -> None:
    shipped = (ROOT / "docs" / "BEHAVIOURS.md").read_text(encoding="utf-8")
    assert shipped == listing(capsys), "stale: run `.venv/bin/hfsm-run --list > docs/BEHAVIOURS.md`"


def test_every_builtin_primitive_and_machine_is_listed_with_its_signature(
    capsys: pytest.CaptureFixture[str],
) -> None:
    text = listing(capsys)
    names = re.findall(r"^### `(\w+)`$", text, flags=re.M)
    machines = sorted(p.stem for p in (ROOT / "machines").glob("*.yaml"))
    assert names == [*BUILTINS, *sorted(p.spec.name for p in primitives()), *machines]
    entry = text.split("### `walk_randomly`")[1].split("###")[0]
    assert "- params: `distance: float = 1.0`, `step: float = 0.25`" in entry
    assert "- outcomes: `done`, `bumped`" in entry and "world `sim`" in entry


def test_lib_adds_its_machines(machine: Callable[[str, str], Path], capsys: pytest.CaptureFixture[str]) -> None:
    path = machine("greet", """
        doc: |
          Say hello.

          More text that is not the first paragraph.
        params: {who: {type: str, default: world, doc: whom to greet}}
        outcomes: [done, failure]
        outputs: {said: "${params.who}"}
        states:
          a: {do: log, with: {text: hi}, on: {done: done}}
    """)
    entry = listing(capsys, "--lib", str(path.parent)).split("### `greet`")[1].split("###")[0]
    assert entry.splitlines()[2].startswith("Say hello. (machine ")
    assert '`who: str = "world"` (whom to greet)' in entry
    assert "- failures: `failure`" in entry and "- outputs: `said`" in entry


def test_the_readme_primitive_is_the_code() -> None:
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    block = readme.split("## Primitives\n")[1].split("```python\n")[1].split("```")[0]
    name = re.search(r"^def (\w+)\(", block, flags=re.M)
    assert name is not None and "@primitive(" in block
    prim = next(p for p in primitives() if p.spec.name == name.group(1))
    source = Path(prim.fn.__code__.co_filename).read_text(encoding="utf-8")
    assert block in source


def names(text: str) -> list[str]:
    return re.findall(r"^### `(\w+)`", text, flags=re.M)


def test_a_pattern_lists_the_behaviours_whose_name_or_world_matches(capsys: pytest.CaptureFixture[str]) -> None:
    assert names(listing(capsys, "tararc_t")) == ["tararc_task"]
    assert set(names(listing(capsys, "tararc_*"))) == {n for n in names(listing(capsys)) if n.startswith("tararc_")}
    sim = names(listing(capsys, "sim"))
    assert "scan_for_table" in sim and "wait" not in sim and "move_furniture" not in sim
    text = listing(capsys, "no_such_thing")
    assert names(text) == [] and "No behaviour's name or world matches 'no_such_thing'" in text


def test_the_listing_speaks_to_users(capsys: pytest.CaptureFixture[str]) -> None:
    text = listing(capsys)
    assert "regenerate" not in text and ".venv" not in text and "SPEC" not in text and "test fails" not in text


def test_with_a_file_the_machines_beside_it_are_listed(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    for name in ("mine", "neighbour"):
        (tmp_path / f"{name}.yaml").write_text("outcomes: [done]\nstates:\n  a: {do: wait, on: {done: done}}\n")
    assert main([str(tmp_path / "mine.yaml"), "--list", "neighbour"]) == 0
    assert names(capsys.readouterr().out) == ["neighbour"]
