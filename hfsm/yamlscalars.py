"""Plain scalars read as the YAML 1.2 core schema: `on`, `yes` stay strings; NaN and infinities are
refused; a text seen before is not resolved again."""

from __future__ import annotations

import math
import re
from typing import Any

CORE = "tag:yaml.org,2002:"


def _int(text: str) -> int:
    if text.startswith(("0o", "0x")):
        return int(text[2:], 8 if text[1] == "o" else 16)
    return int(text)


def _float(text: str) -> float:
    lowered = text.lower()
    if lowered.endswith((".inf", ".nan")):
        raise ValueError(text)
    value = float(text)
    if not math.isfinite(value):
        raise ValueError(text)
    return value


def _bool(text: str) -> bool:
    if text.lower() not in ("true", "false"):
        raise ValueError(text)
    return text.lower() == "true"


def _null(text: str) -> None:
    if text not in ("", "~", "null", "Null", "NULL"):
        raise ValueError(text)


CONVERT: dict[str, Any] = {"str": str, "int": _int, "float": _float, "bool": _bool, "null": _null}
NOT_VALID = {"float": "is not a finite number (NaN and infinities are refused)"}

# The YAML 1.2 core schema's implicit types: (first characters, kind, pattern).
_IMPLICIT = (
    ("tTfF", "bool", r"^(?:true|True|TRUE|false|False|FALSE)$"),
    ("~nN", "null", r"^(?:~|null|Null|NULL)$"),
    ("-+0123456789", "int", r"^(?:[-+]?[0-9]+|0o[0-7]+|0x[0-9a-fA-F]+)$"),
    (
        "-+0123456789.",
        "float",
        r"^(?:[-+]?(?:\.[0-9]+|[0-9]+(?:\.[0-9]*)?)(?:[eE][-+]?[0-9]+)?"
        r"|[-+]?\.(?:inf|Inf|INF)|\.(?:nan|NaN|NAN))$",
    ),
)
_BY_FIRST: dict[str, list[tuple[str, re.Pattern[str]]]] = {}
for _chars, _kind, _pattern in _IMPLICIT:
    for _ch in _chars:
        _BY_FIRST.setdefault(_ch, []).append((_kind, re.compile(_pattern)))


def implicit_kind(text: str) -> str | None:
    for kind, pattern in _BY_FIRST.get(text[0], ()):
        if pattern.match(text):
            return kind
    return None


CONVERT_ME: Any = object()


class PlainScalars(dict[str, Any]):
    """Plain scalar text -> its value, for texts seen before; CONVERT_ME when it needs checking."""

    def __missing__(self, text: str) -> Any:
        if not text:
            return None
        kind = implicit_kind(text)
        try:
            value = text if kind is None else CONVERT[kind](text)
        except ValueError:
            return CONVERT_ME  # reported, at each place, by the slow path
        if len(self) < 10_000:
            self[text] = value
        return value
