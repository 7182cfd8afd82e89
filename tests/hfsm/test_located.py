from __future__ import annotations

import pytest
from pydantic import BaseModel, ConfigDict

from hfsm.errors import UserError
from hfsm.located import validate
from hfsm.model import Machine
from hfsm.yamlio import parse_text


def errors(text: str) -> list[str]:
    with pytest.raises(UserError) as info:
        validate(Machine, parse_text(text, "m.yaml"))
    return [f.format() for f in info.value.findings]


def test_unknown_keys_with_suggestions_at_their_positions() -> None:
    found = errors(
        "outcomes: [done]\ntimr: 3\nstates:\n  a:\n    do: wait\n    tiemr: 3\n    on: {done: done}\n"
    )
    assert found == [
        "m.yaml:2:1: error[E200]: unknown key 'timr'; did you mean 'timer'?",
        "m.yaml:6:5: error[E200]: unknown key 'tiemr'; did you mean 'timer'?",
    ]


def test_bad_names_types_and_timers_all_at_once() -> None:
    found = errors(
        "outcomes: [done]\nparams:\n  x: {type: flot}\nstates:\n  Bad:\n    do: wait\n    timer: -1\n"
        "  c:\n    choose:\n      - else: done\n        foo: 1\n  d: [1]\n"
    )
    assert any(":3:13:" in f and "did you mean 'float'" in f for f in found)
    assert any(":5:3:" in f and "bad name 'Bad'" in f for f in found)
    assert any(":7:12:" in f and "'timer' must be a number of seconds > 0" in f for f in found)
    assert any(":11:9:" in f and "unknown key 'foo'" in f for f in found)
    assert any(":12:6:" in f and "'d' must be a mapping" in f for f in found)


def test_missing_required_keys() -> None:
    assert errors("doc: x\n") == [
        "m.yaml:1:1: error[E200]: missing required key 'outcomes'",
        "m.yaml:1:1: error[E200]: missing required key 'states'",
    ]


def test_strict_types_no_coercion() -> None:
    found = errors("outcomes: [done]\ntimer: true\nstates:\n  a: {do: wait, on: {done: done}}\n")
    assert len(found) == 1 and "not true" in found[0]


def test_on_key_is_not_a_boolean() -> None:
    text = (
        "outcomes: [done]\nstates:\n  on: {do: wait, on: {done: off}}\n  off: {do: wait, on: {done: done}}\n"
    )
    model = validate(Machine, parse_text(text, "m.yaml"))
    assert list(model.states) == ["on", "off"]


class _Item(BaseModel):
    model_config = ConfigDict(extra="forbid")
    difficulty: float = 0.5


class _Items(BaseModel):
    model_config = ConfigDict(extra="forbid")
    items: list[_Item] | None = None


def test_a_misspelt_key_in_an_optional_list_gets_a_suggestion() -> None:
    """As a scenario's `tables: list[TableSpec] | None`: the keys are the items' own."""
    with pytest.raises(UserError) as info:
        validate(_Items, parse_text("items:\n  - {dificulty: 0.5}\n", "s.yaml"))
    assert [f.format() for f in info.value.findings] == [
        "s.yaml:2:6: error[E200]: unknown key 'dificulty'; did you mean 'difficulty'?"
    ]
