"""`--fail AGENT@SECONDS`: fail an agent in any world (docs/REFERENCE.md#agents-that-fail), checked before
anything runs."""

from __future__ import annotations

import argparse
import math
from collections.abc import Sequence
from typing import TYPE_CHECKING

from hfsm.errors import UsageError
from hfsm.names import did_you_mean

if TYPE_CHECKING:  # the interpreter is loaded only to run, not to check
    from hfsm.runtime.failing import Failure


def fail_arg(text: str) -> Failure:
    """Read one `--fail` value (argparse reports a problem and exits 2)."""
    agent, sep, seconds = text.rpartition("@")
    if not sep or not agent:
        raise argparse.ArgumentTypeError(f"{text!r}: write AGENT@SECONDS, e.g. r2@60")
    try:
        value = float(seconds)
    except ValueError:
        value = math.nan
    if not math.isfinite(value) or value < 0:
        raise argparse.ArgumentTypeError(f"{text!r}: SECONDS must be a number >= 0, not {seconds!r}")
    from hfsm.runtime.failing import Failure

    return Failure(agent, value)


def check_failures(failures: Sequence[Failure], agents: Sequence[str]) -> None:
    problems = [
        f"--fail {f.agent}@{f.seconds:g}: no agent named '{f.agent}'"
        + (did_you_mean(f.agent, agents) or f" (agents: {', '.join(agents)})")
        for f in failures
        if f.agent not in agents
    ]
    if problems:
        raise UsageError("\n".join(problems))
