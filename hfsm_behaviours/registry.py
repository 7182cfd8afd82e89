"""The `hfsm.primitives` entry point: every primitive of this package, declared as data.

`primitives.json` holds their declarations, so checking, listing and drawing machines never import
the simulator; a function is imported when a run first calls it. Regenerate it after adding or
changing a primitive (a test fails when it is stale):

    make declarations
"""

from __future__ import annotations

from importlib.resources import files
from importlib.resources.abc import Traversable

from hfsm.declarations import loads
from hfsm.primitive import Primitive
from hfsm.registry import Problem, Registry

DECLARATIONS = "primitives.json"


def register(registry: Registry) -> None:
    """Add this package's primitives to a registry, from their declarations, and the check of the
    `history` param (TARARC's history file, `hfsm-run --history FILE`)."""
    registry.add(*loads(files("hfsm_behaviours").joinpath(DECLARATIONS).read_text(encoding="utf-8")))
    registry.check_param("history", history_problems)


def history_problems(value: object) -> list[Problem]:
    """Every problem of the history file `value` names, before a run (`history_file.problems`)."""
    from hfsm_behaviours.tararc.history_file import (
        problems,  # pure, no simulator; only when a history is given
    )

    return problems(value)


def machines() -> Traversable:
    """The `hfsm.machines` entry point: the paper's machines, shipped in the package."""
    return files("hfsm_behaviours") / "machines"


def primitives() -> tuple[Primitive, ...]:
    """The primitives themselves (imports the simulator): what `primitives.json` is made from."""
    from hfsm_behaviours import approach, carry, drive, teamwork

    return (*approach.PRIMITIVES, *carry.PRIMITIVES, *drive.PRIMITIVES, *teamwork.PRIMITIVES)
