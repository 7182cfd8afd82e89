"""The collaboration history: C_ij, n_s, n_f per pair and per robot, and the last belief degrees.

A value, never mutated: `record_run` returns the history after a run. C_ij is not stored, it is
`n_s + n_f > 0` of the pair, so it cannot disagree with the counts.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from itertools import combinations

from hfsm_behaviours.tararc.formulas import powered_rate, relevance
from hfsm_behaviours.tararc.grouping import Pair, pair


@dataclass(frozen=True)
class Record:
    """Successful and failed collaborations (of a pair) or tasks (of a robot)."""

    n_s: int = 0
    n_f: int = 0

    def __post_init__(self) -> None:
        if self.n_s < 0 or self.n_f < 0:
            raise ValueError(f"counts must be >= 0, got n_s={self.n_s}, n_f={self.n_f}")

    def after(self, ok: bool) -> Record:
        return Record(self.n_s + 1, self.n_f) if ok else Record(self.n_s, self.n_f + 1)


@dataclass(frozen=True)
class History:
    """Records with no collaboration (0, 0) are dropped: they are the same as no record."""

    pairs: Mapping[Pair, Record] = field(default_factory=dict)
    robots: Mapping[str, Record] = field(default_factory=dict)
    beliefs: Mapping[str, float] = field(default_factory=dict)

    def __post_init__(self) -> None:
        for a, b in self.pairs:
            if a >= b:
                raise ValueError(f"pair key ({a!r}, {b!r}) must be two ids in increasing order")
        object.__setattr__(self, "pairs", {k: r for k, r in sorted(self.pairs.items()) if r != Record()})
        object.__setattr__(self, "robots", {k: r for k, r in sorted(self.robots.items()) if r != Record()})
        object.__setattr__(self, "beliefs", dict(sorted(self.beliefs.items())))

    def pair_record(self, a: str, b: str) -> Record:
        return self.pairs.get(pair(a, b), Record())

    def robot_record(self, robot: str) -> Record:
        return self.robots.get(robot, Record())


def relevance_matrix(history: History, ids: Iterable[str] | None = None) -> dict[Pair, float]:
    """R_ij (eq. 1) of every recorded pair, or only of pairs among `ids`; zero pairs are left out."""
    keep = None if ids is None else set(ids)
    out: dict[Pair, float] = {}
    for key, rec in sorted(history.pairs.items()):
        if keep is not None and not (key[0] in keep and key[1] in keep):
            continue
        r = relevance(rec.n_s, rec.n_f)
        if r > 0.0:
            out[key] = r
    return out


def p_term(history: History, robot: str) -> float:
    """P_j^beta of eq. 3 from the robot's own task record (see formulas.belief)."""
    rec = history.robot_record(robot)
    return powered_rate(rec.n_s, rec.n_f)


def record_run(
    history: History,
    groups: Sequence[Sequence[str]],
    outcomes: Sequence[bool],
    beliefs: Mapping[str, float] | None = None,
) -> History:
    """The history after a run: group g succeeded iff outcomes[g].

    Every pair of robots that worked in the same group gains a success or a failure, and so does
    every robot; the belief degrees of this run replace those of the robots they name.
    """
    if len(groups) != len(outcomes):
        raise ValueError(f"{len(groups)} groups but {len(outcomes)} outcomes")
    seen: set[str] = set()
    for members in groups:
        for m in members:
            if m in seen:
                raise ValueError(f"robot {m!r} is in two groups")
            seen.add(m)
    pairs = dict(history.pairs)
    robots = dict(history.robots)
    for members, ok in zip(groups, outcomes, strict=True):
        for a, b in combinations(sorted(members), 2):
            pairs[(a, b)] = pairs.get((a, b), Record()).after(ok)
        for m in members:
            robots[m] = robots.get(m, Record()).after(ok)
    merged = dict(history.beliefs)
    merged.update(beliefs or {})
    return History(pairs, robots, merged)
