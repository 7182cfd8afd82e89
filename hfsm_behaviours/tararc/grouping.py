"""Grouping and agent election (TARARC section 4.3, steps 2-4), deterministic.

Robots are named by id; every tie is broken by id (the smaller string wins) and the input order
never matters, so every robot computes the same groups from the same broadcasts.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass

Pair = tuple[str, str]
Relevance = Mapping[Pair, float]
"""R_ij by `pair(i, j)`; a missing pair has relevance 0 (never worked together)."""

BeliefOf = Callable[[str, int], float]
"""F of a robot at a given place (j_ord) in its group."""


@dataclass(frozen=True)
class Ties:
    """How step 2 breaks ties of relevance before the id (robots with no history all tie): `seed`
    ranks robots of equal row sums to seed a group (smaller first), `partner(seed, robot)` ranks
    robots of equal relevance to the seed (smaller first). Both must be pure functions of what every
    robot knows (positions said in the broadcast, the task list), so that every robot agrees."""

    seed: Callable[[str], float]
    partner: Callable[[str, str], tuple[float, ...]]


def pair(a: str, b: str) -> Pair:
    """The key of an unordered pair: R is symmetric (R_ij = R_ji)."""
    return (a, b) if a <= b else (b, a)


@dataclass(frozen=True)
class Robot:
    id: str
    x: float
    y: float


@dataclass(frozen=True)
class Group:
    """A group: `members` in join order (index = j_ord, the greedy seed first), `agent` among them."""

    agent: str
    members: tuple[str, ...]

    def __post_init__(self) -> None:
        if self.agent not in self.members:
            raise ValueError(f"agent {self.agent!r} is not a member of {self.members}")
        if len(set(self.members)) != len(self.members):
            raise ValueError(f"a robot appears twice in {self.members}")

    def order(self, robot: str) -> int:
        """j_ord: the robot's place in the group."""
        return self.members.index(robot)


def group_size(n_robots: int, n_groups: int) -> tuple[int, int]:
    """(n, x): every group has n = floor(N_r/N_g) robots, and x of them one more."""
    if n_groups < 1:
        raise ValueError(f"need at least one group, got {n_groups}")
    if n_robots < n_groups:
        raise ValueError(f"{n_robots} robots cannot make {n_groups} groups (merge tasks first)")
    return n_robots // n_groups, n_robots % n_groups


def row_sum(robot: str, others: Iterable[str], rel: Relevance) -> float:
    return math.fsum(rel.get(pair(robot, o), 0.0) for o in others if o != robot)


def greedy_groups(
    ids: Iterable[str], n_groups: int, rel: Relevance, ties: Ties | None = None
) -> tuple[list[tuple[str, ...]], list[str]]:
    """Step 2: N_g groups of n robots each, and the x robots left over.

    The ungrouped robot with the largest row sum of R (over ungrouped robots: the relevance of
    grouped ones is zeroed) seeds a group and takes its n-1 most relevant ungrouped partners.
    Ties go by `ties` (if given), then by id.
    """
    pool = sorted(set(ids))
    n, _ = group_size(len(pool), n_groups)
    groups: list[tuple[str, ...]] = []
    known: dict[str, list[tuple[str, float]]] = {}  # each robot's pairs that R holds (others are 0)
    for (a, b), value in rel.items():
        if a < b:  # the keys `pair` makes; row_sum reads no other
            known.setdefault(a, []).append((b, value))
            known.setdefault(b, []).append((a, value))

    def seed_key(r: str) -> tuple[float, float, str]:
        # row_sum(r, pool, rel): fsum is exactly rounded, so leaving out the zeros of pairs R does
        # not hold changes nothing
        total = math.fsum([v for o, v in known.get(r, ()) if o in in_pool])
        return (-total, ties.seed(r) if ties else 0.0, r)

    def partner_key(seed: str, r: str) -> tuple[float, tuple[float, ...], str]:
        return (-rel.get(pair(seed, r), 0.0), ties.partner(seed, r) if ties else (), r)

    in_pool: set[str] = set()
    for _ in range(n_groups):
        in_pool = set(pool)
        seed = min(pool, key=seed_key)
        rest = [r for r in pool if r != seed]
        partners = sorted(rest, key=lambda r: partner_key(seed, r))[: n - 1]
        groups.append((seed, *partners))
        taken = {seed, *partners}
        pool = [r for r in pool if r not in taken]
    return groups, pool


def elect(members: Sequence[str], belief_of: BeliefOf) -> str:
    """Step 3: the member with the highest belief degree F (at its j_ord) is the agent; ties by id."""
    if not members:
        raise ValueError("cannot elect an agent of an empty group")
    return min(members, key=lambda r: (-belief_of(r, members.index(r)), r))


def distance(a: Robot, b: Robot) -> float:
    return math.hypot(a.x - b.x, a.y - b.y)


def place_leftovers(
    groups: Sequence[Group], leftovers: Iterable[str], robots: Mapping[str, Robot]
) -> list[Group]:
    """Step 4: each of the last x groups, in order, takes the leftover nearest its agent (ties by id)."""
    left = sorted(set(leftovers))
    if len(left) > len(groups):
        raise ValueError(f"{len(left)} leftover robots for {len(groups)} groups")
    out = list(groups)
    first = len(groups) - len(left)
    for g in range(first, len(groups)):
        agent = robots[out[g].agent]
        nearest = min(left, key=lambda r: (distance(robots[r], agent), r))
        left.remove(nearest)
        out[g] = Group(out[g].agent, (*out[g].members, nearest))
    return out


def form_groups(robots: Iterable[Robot], n_groups: int, rel: Relevance, belief_of: BeliefOf,
                ties: Ties | None = None) -> list[Group]:
    """Steps 2-4 together: greedy groups (relevance ties by `ties`, then id), elected agents,
    leftovers matched by distance to agents."""
    by_id: dict[str, Robot] = {}
    for robot in robots:
        if robot.id in by_id:
            raise ValueError(f"robot id {robot.id!r} appears twice")
        by_id[robot.id] = robot
    cores, leftovers = greedy_groups(by_id, n_groups, rel, ties)
    elected = [Group(elect(core, belief_of), core) for core in cores]
    return place_leftovers(elected, leftovers, by_id)


def group_of(groups: Sequence[Group], robot: str) -> int:
    """The index of the group the robot belongs to."""
    for i, group in enumerate(groups):
        if robot in group.members:
            return i
    raise KeyError(robot)
