from __future__ import annotations

import pytest

from hfsm.primitive import Context, primitive
from hfsm.registry import Registry


@primitive(outcomes=["done"], world="sim")
def move(ctx: Context) -> str:
    return "done"


@primitive(outcomes=["done", "failure"])
def think(ctx: Context) -> str:
    return "done"


def test_for_world_keeps_world_free_primitives_and_names_the_others() -> None:
    kept = Registry([move, think]).for_world("none")
    assert kept.names() == ["think"] and kept.elsewhere == {"move": "sim"}
    assert Registry([move, think]).for_world("sim").names() == ["move", "think"]


def test_failures_default_to_outcomes_named_failure() -> None:
    assert think.spec.failures == {"failure"} and move.spec.failures == frozenset()


def test_a_name_registered_twice_is_refused() -> None:
    with pytest.raises(ValueError, match="registered twice"):
        Registry([move, move])


def test_discovery_finds_the_behaviours_plugin() -> None:
    assert {"go_to_table", "land_table"} <= set(Registry.discover().names())


def test_a_param_check_is_kept_for_every_world_and_registered_once() -> None:
    registry = Registry([move, think])
    registry.check_param("history", lambda value: [("h.json", 1, 1, f"bad {value}")])
    assert registry.for_world("none").param_checks["history"]("x") == [("h.json", 1, 1, "bad x")]
    with pytest.raises(ValueError, match="param 'history' has a check already"):
        registry.check_param("history", lambda value: [])


def test_discovery_finds_the_history_check() -> None:
    check = Registry.discover().param_checks["history"]
    assert check("") == [] and check("/no/such/folder/h.json")[0][3].startswith("the history is written")
