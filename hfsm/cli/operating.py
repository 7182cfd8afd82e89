"""The operator's flags of `hfsm-run`: the autonomy level, a script or a trace of
decisions, breakpoints, and resuming a recorded run."""

from __future__ import annotations

import argparse
from collections.abc import Callable, Collection
from pathlib import Path

from hfsm.autonomy import LEVELS
from hfsm.errors import Finding, UserError
from hfsm.load import Loaded
from hfsm.runtime.breaks import Breakpoint, compiled, condition_names


def _break(text: str) -> object:
    from hfsm.runtime.breaks import parse

    try:
        return parse(text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def add_arguments(p: argparse.ArgumentParser) -> None:
    group = p.add_argument_group("operator")
    group.add_argument(
        "--autonomy",
        choices=LEVELS,
        default="full",
        help="the run's autonomy level: arcs that need more wait for the operator (default full)",
    )
    group.add_argument(
        "--operator",
        type=Path,
        metavar="FILE",
        help="the operator's decisions: a YAML list of {t, agent, do, event, level}, or a trace "
        "(.jsonl) whose operator records are replayed",
    )
    group.add_argument(
        "--break",
        dest="breaks",
        action="append",
        type=_break,
        default=[],
        metavar="KIND:PATTERN[@AGENT]",
        help="pause the run after a record that matches (enter:grasp/*, event:failed, send:lift@r1, …), "
        "or when a condition over vars and in turns true (cond:'vars.n > 3'@r1)",
    )
    group.add_argument(
        "--resume",
        metavar="TRACE@T",
        help="run again what TRACE recorded up to T seconds (its flags, its operator records; checked "
        "byte for byte), then go on with the machine files as they are now",
    )


def conditions(
    breaks: list[Breakpoint], loaded: Loaded, inputs: Callable[[], Collection[str]]
) -> list[Breakpoint]:
    """The breakpoints with their conditions compiled against the run's vars and its world's inputs;
    every bad one at once, at its column in the flag's text (exit 2)."""
    if not any(b.kind == "cond" for b in breaks):
        return breaks
    names = condition_names((mf.model for mf in loaded.machines.values()), inputs())
    done, problems = compiled(breaks, names)
    if problems:
        raise UserError(Finding("--break", 1, p.col, p.code, str(p), end=(1, p.end)) for p in problems)
    return done
