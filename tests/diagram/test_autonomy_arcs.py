"""An arc that needs an autonomy level is coloured and labelled with its level, as FlexBE's
editor shows them; the legend says so."""

from __future__ import annotations

from pathlib import Path

from hfsm.diagram.dot import LEVEL_COLOURS, to_dot
from hfsm.diagram.extract import Sources, machine_figure
from hfsm.diagram.legend import legend
from hfsm.load import load
from hfsm.registry import Registry

CASES = Path(__file__).resolve().parents[1] / "spec" / "operator"


def _figure(name: str) -> str:
    registry = Registry.discover()
    loaded = load([CASES / f"{name}.yaml"], registry=registry)
    return to_dot(machine_figure(name, Sources.from_loaded(loaded, registry)))


def test_held_arcs_carry_their_level_and_colour() -> None:
    dot = _figure("grasp")
    failed = next(line for line in dot.splitlines() if 'label="failed (high)"' in line)
    assert f'color="{LEVEL_COLOURS["high"]}"' in failed
    timeout = next(line for line in dot.splitlines() if 'label="timeout (low)"' in line)
    assert f'color="{LEVEL_COLOURS["low"]}"' in timeout
    done = next(line for line in dot.splitlines() if 'label="done"' in line and "carry" in line)
    assert "color=" not in done


def test_a_join_rule_that_needs_a_level_is_marked() -> None:
    dot = _figure("joined")
    rule = next(line for line in dot.splitlines() if "(high)" in line and "->" in line)
    assert f'color="{LEVEL_COLOURS["high"]}"' in rule


def test_the_legend_explains_the_colour() -> None:
    dot = to_dot(legend())
    assert "operator answers (autonomy:)" in dot
    assert f'color="{LEVEL_COLOURS["high"]}"' in dot
