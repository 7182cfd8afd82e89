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


def is_name(text: object) -> bool:
    return isinstance(text, str) and NAME_RE.match(text) is not None


def did_you_mean(name: str, candidates: Iterable[str]) -> str:
    """A sentence tail suggesting the closest candidate, or '' when none is close."""
    close = difflib.get_close_matches(name, sorted(set(candidates)), n=1, cutoff=0.6)
    return f"; did you mean '{close[0]}'?" if close else ""
