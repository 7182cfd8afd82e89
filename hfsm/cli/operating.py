"""The operator's flags of `hfsm-run`: the autonomy level, a script or a trace of
decisions, breakpoints, and resuming a recorded run."""

from __future__ import annotations

import argparse
from pathlib import Path

from hfsm.autonomy import LEVELS


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
        help="pause the run after a record that matches (enter:grasp/*, event:failed, send:lift@r1, …)",
    )
    group.add_argument(
        "--resume",
        metavar="TRACE@T",
        help="run again what TRACE recorded up to T seconds (its flags, its operator records; checked "
        "byte for byte), then go on with the machine files as they are now",
    )
