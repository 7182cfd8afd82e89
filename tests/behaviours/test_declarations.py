"""hfsm_behaviours/primitives.json says what the primitives themselves say, and a run finds them."""

from __future__ import annotations

from pathlib import Path

from hfsm import declarations
from hfsm.registry import Registry
from hfsm_behaviours.registry import DECLARATIONS, primitives

ROOT = Path(__file__).resolve().parents[2]


def test_the_declarations_file_is_fresh() -> None:
    shipped = (ROOT / "hfsm_behaviours" / DECLARATIONS).read_text(encoding="utf-8")
    assert shipped == declarations.dumps(primitives()), "stale: run `make declarations`"


def test_declared_primitives_have_the_functions_specs_and_load_them_when_called() -> None:
    found = {p.spec.name: p for p in Registry.discover()}
    for prim in primitives():
        declared = found[prim.spec.name]
        assert declared.spec == prim.spec
        assert isinstance(declared.target, str) and declared.fn is prim.fn


def test_declarations_round_trip() -> None:
    again = declarations.loads(declarations.dumps(primitives()))
    assert [p.spec for p in again] == [p.spec for p in primitives()]
    assert [p.where for p in again] == [p.where for p in primitives()]
