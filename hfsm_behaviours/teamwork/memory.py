"""The collaboration history between runs: read this robot's part at the start, update the file at the end."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from hfsm.primitive import Context, Outcome, primitive
from hfsm_behaviours.tararc.history import History
from hfsm_behaviours.tararc.history_file import load, save
from hfsm_behaviours.tararc.outcome import group_outcomes, merge_into, record_team
from hfsm_behaviours.tararc.plan import history_of, record_of
from hfsm_behaviours.teamwork.plans import coefficients_from


def _read(history: str) -> History:
    """The file's history; an empty one when `history` is "" or names no file yet (the first run)."""
    if not history or not Path(history).exists():
        return History()
    return load(Path(history))


@primitive(outcomes=["recalled"], outputs=["record"])
def tararc_recall(ctx: Context, *, history: str = "") -> Outcome:
    """This robot's part of the history file (its task record, its last F, its pairs), to say to the team."""
    return Outcome("recalled", record=record_of(_read(history), ctx.agent))


@primitive(outcomes=["remembered"], outputs=["outcomes"])
def tararc_remember(
    ctx: Context,
    *,
    history: str = "",
    first: dict[str, Any],
    last: dict[str, Any],
    lost: list[Any],
    reports: dict[str, Any],
    ok: bool,
    coefficients: dict[str, Any],
) -> Outcome:
    """Each group's outcome (every robot left in it reported `ok`) and, when `history` names a file,
    that file updated with this run (written atomically; robots of other teams are kept).

    Every robot of the team writes the same update from the same reports, so the order does not matter.
    """
    said = {str(r): bool(v.get("ok", False)) for r, v in reports.items()}
    said[ctx.agent] = ok
    outcomes = group_outcomes(last, said)
    if history:
        before = history_of({r: {"record": rec} for r, rec in first["records"].items()})
        gone = [str(r) for r in lost]
        after = record_team(before, first, last, gone, outcomes, coefficients_from(coefficients))
        save(Path(history), merge_into(_read(history), list(first["records"]), after))
    return Outcome("remembered", outcomes=outcomes)
