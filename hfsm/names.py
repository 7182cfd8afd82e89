"""Names in machine files, and suggestions for misspelt ones."""

from __future__ import annotations

import difflib
import re
from collections.abc import Iterable

NAME_PATTERN = r"^[a-z][a-z0-9_]*$"
NAME_RE = re.compile(NAME_PATTERN)
NAME_RULE = "a lowercase letter, then lowercase letters, digits and '_'"
RESERVED_OUTCOMES = frozenset({"error"})
RESERVED_MESSAGES = frozenset({"timeout", "error"})
KEEP = ("all", "last")  # send's `keep`: every copy kept until taken, or the sender's newest


def is_name(text: object) -> bool:
    return isinstance(text, str) and NAME_RE.match(text) is not None


def did_you_mean(name: str, candidates: Iterable[str]) -> str:
    """A sentence tail suggesting the closest candidate, or '' when none is close."""
    close = difflib.get_close_matches(name, sorted(set(candidates)), n=1, cutoff=0.6)
    return f"; did you mean '{close[0]}'?" if close else ""


def did_you_mean_kinds(name: str, kinds: dict[str, Iterable[str]]) -> str:
    """A sentence tail suggesting the closest candidate of each kind (`state 'a' or outcome 'b'`),
    or of the one kind that has a close one; '' when none is close."""
    close = {
        kind: found[0]
        for kind, names in kinds.items()
        if (found := difflib.get_close_matches(name, sorted(set(names)), n=1, cutoff=0.6))
    }
    if len(set(close.values())) <= 1:
        return f"; did you mean '{next(iter(close.values()))}'?" if close else ""
    return "; did you mean " + " or ".join(f"{kind} '{found}'" for kind, found in close.items()) + "?"
