"""Values as text (docs/REFERENCE.md#expressions): strings as they are, numbers in their fewest digits, lists
and dicts as JSON."""

from __future__ import annotations

import json
import math
from typing import Any

SHORT = 60  # characters of an expression or a name quoted in a message


def short(text: str) -> str:
    """Text quoted in a message: at most SHORT characters."""
    return text if len(text) <= SHORT else text[: SHORT - 1] + "…"


def format_number(value: float) -> str:
    if math.isfinite(value) and value == int(value) and "e" not in repr(value):
        return str(int(value))
    return repr(value)


def to_text(value: Any) -> str:
    """A value as text: strings as they are, numbers in their fewest digits, lists and dicts as JSON."""
    if isinstance(value, str):
        return value
    return _json(value)


def _json(value: Any) -> str:
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return format_number(value)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, list):
        return "[" + ", ".join(_json(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{_json(str(k))}: {_json(v)}" for k, v in value.items()) + "}"
    return _json(str(value))
