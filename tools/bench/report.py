"""Pool the rounds (medians) and write the Markdown: the table, the targets, the call counts."""

from __future__ import annotations

import statistics
from dataclasses import dataclass
from typing import Any

MS = {"w3_load", "w3_compile"}  # cells shown in ms; the others in µs per transition
TARGETS = {"w1": 2.0, "w2": 4.0, "w3_load": 100.0}  # hfsm, trace off
TARGET_TEXT = {
    "w1": "W1 flat ≤ 2 µs/transition (trace off)",
    "w2": "W2 nested ≤ 4 µs/transition (trace off)",
    "w3_load": "W3 load and check of the 500-state chain ≤ 100 ms",
}
ROWS = [  # (label, lib, {column: cell})
    ("hfsm", "hfsm", {"w1": "w1", "w2": "w2", "w3_load": "w3_load", "w3_chain": "w3_chain", "w4": "w4"}),
    ("hfsm, trace on: ListTrace", "hfsm", {"w1": "w1_list", "w2": "w2_list"}),
    ("hfsm, trace on: JSONL to /dev/null", "hfsm", {"w1": "w1_jsonl", "w2": "w2_jsonl"}),
    ("floor (dict table)", "floor", {"w1": "w1", "w2": "w2", "w3_load": "w3_load", "w3_chain": "w3_chain"}),
    (
        "transitions",
        "transitions",
        {"w1": "w1", "w2": "w2", "w3_load": "w3_load", "w3_chain": "w3_chain", "w4": "w4"},
    ),
    (
        "python-statemachine",
        "python-statemachine",
        {"w1": "w1", "w2": "w2", "w3_load": "w3_load", "w3_chain": "w3_chain"},
    ),
    ("sismic", "sismic", {"w1": "w1", "w2": "w2", "w3_load": "w3_load", "w3_chain": "w3_chain", "w4": "w4"}),
]
COLUMNS = {
    "w1": "W1 flat µs/transition",
    "w2": "W2 nested µs/transition",
    "w3_load": "W3 load 500-state YAML ms",
    "w3_chain": "W3 chain µs/transition",
    "w4": "W4 parallel µs/join",
}


@dataclass
class Pooled:
    """One library's cells over all rounds: median value (in the shown unit), spread, sizes."""

    name: str
    version: str
    value: dict[str, float]
    spread: dict[str, float]  # max / min over rounds
    n: dict[str, int]
    calls: dict[str, list[float]]
    errors: dict[str, str]
    skipped: str


def _shown(cell: str, seconds: float) -> float:
    return seconds * (1e3 if cell in MS else 1e6)


def pool(reports: list[dict[str, Any]]) -> Pooled:
    first = reports[0]
    cells: dict[str, list[float]] = {}
    sizes: dict[str, int] = {}
    errors: dict[str, str] = {}
    for report in reports:
        errors.update(report["errors"])
        for cell, got in report["cells"].items():
            cells.setdefault(cell, []).append(_shown(cell, got["seconds"]))
            sizes[cell] = int(got["n"])
    value = {c: statistics.median(v) for c, v in cells.items()}
    spread = {c: max(v) / min(v) for c, v in cells.items() if min(v) > 0}
    calls: dict[str, list[float]] = next((r["calls"] for r in reports if r["calls"]), {})
    return Pooled(first["name"], first["version"], value, spread, sizes, calls, errors, first["skipped"])


def fmt(x: float) -> str:
    if x >= 100:
        return f"{x:,.0f}"
    if x >= 10:
        return f"{x:.1f}"
    if x >= 1:
        return f"{x:.2f}"
    return f"{x:.3f}"


def _value(p: Pooled, cell: str) -> str:
    if cell in p.errors:
        return "FAILED"
    return fmt(p.value[cell]) if cell in p.value else "-"


def table(pooled: dict[str, Pooled]) -> list[str]:
    lines = [
        "| library | version | " + " | ".join(COLUMNS.values()) + " |",
        "|---|---|" + "---:|" * len(COLUMNS),
    ]
    for label, lib, cells in ROWS:
        p = pooled.get(lib)
        if p is None:
            continue
        if p.skipped:
            lines.append(f"| {label} | not installed | " + " | ".join("-" for _ in COLUMNS) + " |")
            continue
        version = p.version if lib != "hfsm" or label == "hfsm" else ""
        shown = [_value(p, cells[col]) if col in cells else "" for col in COLUMNS]
        lines.append(f"| {label} | {version} | " + " | ".join(shown) + " |")
    return lines


def targets(hfsm: Pooled | None) -> list[str]:
    lines = []
    for cell, limit in TARGETS.items():
        if hfsm is None or cell not in hfsm.value:
            lines.append(f"- {TARGET_TEXT[cell]}: **not measured**")
            continue
        got = hfsm.value[cell]
        unit = "ms" if cell in MS else "µs"
        verdict = "**met**" if got <= limit else f"**not met** ({got / limit:.1f}x the target)"
        lines.append(f"- {TARGET_TEXT[cell]}: {fmt(got)} {unit}, {verdict}")
    return lines


def ratios(pooled: dict[str, Pooled]) -> list[str]:
    """Each library's median over hfsm's, per column (how many times hfsm's cost)."""
    hfsm = pooled.get("hfsm")
    if hfsm is None:
        return []
    lines = ["| library | " + " | ".join(COLUMNS.values()) + " |", "|---|" + "---:|" * len(COLUMNS)]
    for label, lib, cells in ROWS:
        p = pooled.get(lib)
        if lib == "hfsm" or p is None or p.skipped:
            continue
        shown = []
        for col, cell in cells.items():
            base, got = hfsm.value.get(col), p.value.get(cell)
            shown.append(f"{got / base:.2g}x" if base and got else "-")
        lines.append(f"| {label} | " + " | ".join(shown) + " |")
    return lines


def calls_table(pooled: dict[str, Pooled]) -> list[str]:
    heads = {"w1": "W1", "w2": "W2", "w3_chain": "W3 chain", "w4": "W4 (a join)"}
    lines = ["| library | " + " | ".join(heads.values()) + " |", "|---|" + "---:|" * len(heads)]
    for label, lib, _ in ROWS:
        p = pooled.get(lib)
        if p is None or p.skipped or "trace" in label:
            continue
        shown = [f"{c[0]:,.0f} / {c[1]:,.0f}" if (c := p.calls.get(h)) else "-" for h in heads]
        lines.append(f"| {label} | " + " | ".join(shown) + " |")
    return lines


def sizes(pooled: dict[str, Pooled]) -> str:
    parts = []
    for _, lib, cells in ROWS:
        p = pooled.get(lib)
        if p is None or p.skipped or lib == "hfsm":
            continue
        parts.append(f"{p.name}: " + ", ".join(f"{col} {p.n[c]:,}" for col, c in cells.items() if c in p.n))
    return "; ".join(parts)


def spread(pooled: dict[str, Pooled], rounds: int) -> str:
    worst = [(s, p.name, c) for p in pooled.values() for c, s in p.spread.items()]
    if not worst or rounds < 2:
        return "not measured (one round)"
    s, name, cell = max(worst)
    low = min(w[0] for w in worst)
    return f"{low:.2f}x to {s:.2f}x (widest: {name} {cell})"
