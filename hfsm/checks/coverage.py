"""Whether a parallel state's join rules cover every combination of its regions' outcomes
(docs/REFERENCE.md#parallel-states).

Each rule is a box in the product of the regions' outcome sets; the join cannot hang when the boxes
cover the product. That is a tautology check, exponential at worst, so the search goes region by
region carrying only the rules still alive, splits a region's outcomes into classes that keep the
same rules alive (they lead to the same subtree), stops as soon as a rule no longer constrains the
regions left (all below is covered), and remembers each (region, rules alive) it has solved. Six
regions of five outcomes take about a millisecond; docs/PERFORMANCE.md has the numbers.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from math import prod

Rule = Mapping[str, frozenset[str]]  # region -> the outcomes the rule accepts for it


@dataclass(frozen=True)
class Gap:
    """One combination no rule covers, and how many there are in all."""

    combination: tuple[tuple[str, str], ...]  # (region, outcome), in the regions' order
    count: int
    total: int

    def text(self) -> str:
        return ", ".join(f"{region}={outcome}" for region, outcome in sorted(self.combination))


def uncovered(regions: Mapping[str, Sequence[str]], rules: Sequence[Rule]) -> Gap | None:
    """The first combination (regions in order, outcomes in their order) that no rule covers."""
    names = list(regions)
    outcomes = [list(dict.fromkeys(regions[r])) for r in names]
    if any(not o for o in outcomes):
        return None  # a region that cannot end: nothing to cover
    # A rule as one accepted set per region (None: any outcome), rules naming no region dropped.
    boxes = [tuple(rule.get(r) for r in names) for rule in rules]
    sizes = [len(o) for o in outcomes]
    memo: dict[tuple[int, frozenset[int]], int] = {}

    def count(depth: int, alive: frozenset[int]) -> int:
        """Combinations of the regions from `depth` on that no alive rule covers."""
        if not alive:
            return prod(sizes[depth:])
        if depth == len(names) or any(_free(boxes[i], depth) for i in alive):
            return 0
        key = (depth, alive)
        if key not in memo:
            memo[key] = sum(len(group) * count(depth + 1, keep) for keep, group in _classes(depth, alive))
        return memo[key]

    def _classes(depth: int, alive: frozenset[int]) -> list[tuple[frozenset[int], list[str]]]:
        groups: dict[frozenset[int], list[str]] = {}
        for outcome in outcomes[depth]:
            keep = frozenset(i for i in alive if _accepts(boxes[i][depth], outcome))
            groups.setdefault(keep, []).append(outcome)
        return list(groups.items())

    everything = frozenset(range(len(boxes)))
    missing = count(0, everything)
    if missing == 0:
        return None
    combination: list[tuple[str, str]] = []
    alive = everything
    for depth, name in enumerate(names):
        for outcome in outcomes[depth]:
            keep = frozenset(i for i in alive if _accepts(boxes[i][depth], outcome))
            if count(depth + 1, keep) > 0:
                combination.append((name, outcome))
                alive = keep
                break
    return Gap(tuple(combination), missing, prod(sizes))


def _accepts(accepted: frozenset[str] | None, outcome: str) -> bool:
    return accepted is None or outcome in accepted


def _free(box: tuple[frozenset[str] | None, ...], depth: int) -> bool:
    """Whether a rule accepts any outcome of every region from `depth` on."""
    return all(accepted is None for accepted in box[depth:])
