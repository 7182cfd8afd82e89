"""Random parallel states through the whole check: E320 exactly when brute force finds a combination
of outcomes that no rule covers, and the combination it names is one of them."""

from __future__ import annotations

import itertools
import re
import tempfile
from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

from hfsm.errors import Severity, UserError
from hfsm.load import load

Rule = dict[str, list[str]]


def behaviour(k: int) -> str:
    outcomes = ", ".join(f"o{i}" for i in range(k))
    return f"outcomes: [{outcomes}]\nstates:\n  a: {{do: wait, with: {{seconds: 1}}, on: {{done: o0}}}}\n"


@st.composite
def parallel_states(draw: st.DrawFn) -> tuple[dict[str, int], list[Rule]]:
    regions = {f"r{i}": draw(st.integers(1, 3)) for i in range(draw(st.integers(1, 3)))}
    rules = []
    for _ in range(draw(st.integers(1, 5))):
        named = draw(st.lists(st.sampled_from(list(regions)), min_size=1, unique=True))
        outcomes = {r: [f"o{i}" for i in range(regions[r])] for r in named}
        rules.append(
            {r: draw(st.lists(st.sampled_from(outcomes[r]), min_size=1, unique=True)) for r in named}
        )
    return regions, rules


def machine(regions: dict[str, int], rules: list[Rule]) -> str:
    lines = ["outcomes: [done]", "states:", "  s:", "    parallel:"]
    lines += [f"      {r}: {{do: k{k}}}" for r, k in regions.items()]
    lines.append("    join:")
    for rule in rules:
        when = ", ".join(f"{r}: [{', '.join(o)}]" for r, o in rule.items())
        lines.append(f"      - {{when: {{{when}}}, then: done}}")
    return "\n".join(lines) + "\n"


def uncovered(regions: dict[str, int], rules: list[Rule]) -> list[dict[str, str]]:
    names = list(regions)
    combos = itertools.product(*([f"o{i}" for i in range(k)] for k in regions.values()))
    return [
        combo
        for combo in (dict(zip(names, c, strict=True)) for c in combos)
        if not any(all(combo[r] in o for r, o in rule.items()) for rule in rules)
    ]


@settings(max_examples=40)
@given(parallel_states())
def test_a_reported_hang_is_a_real_one(state: tuple[dict[str, int], list[Rule]]) -> None:
    regions, rules = state
    gaps = uncovered(regions, rules)
    with tempfile.TemporaryDirectory() as folder:
        for k in (1, 2, 3):
            Path(folder, f"k{k}.yaml").write_text(behaviour(k), encoding="utf-8")
        top = Path(folder, "top.yaml")
        top.write_text(machine(regions, rules), encoding="utf-8")
        try:
            load([top])
            hang = None
        except UserError as err:
            errors = [f for f in err.findings if f.severity is Severity.ERROR]
            assert [f.code for f in errors] == ["E320"], err
            hang = errors[0]
    if not gaps:
        assert hang is None
        return
    assert hang is not None and (hang.line, hang.col) == (len(regions) + 5, 5)  # at `join:`
    named = re.search(r"no rule holds when (.*?)(?: \(and (\d+) more of \d+ combinations\))?;", hang.message)
    assert named is not None
    combination = dict(pair.split("=") for pair in named.group(1).split(", "))
    assert combination in gaps
    assert int(named.group(2) or 0) + 1 == len(gaps)
