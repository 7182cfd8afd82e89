"""Where each robot stands: forming up round its agent (step 6) and enclosing its task.

The paper puts the common nodes "around the agent" and says no more. A fixed ring (member k at
angle 2πk/m) sends members across a crowd to places where other robots stand; here places are
chosen by where the members are:

- Forming up (`form_places`), for the whole team at once: every agent stays where it is, and each
  member takes, nearest first over the team, the free place nearest it on rings round its agent
  (radius `radius(m, spacing)`, then wider rings), free meaning at least `gap` from every agent and
  every place already taken, inside the box the team and its tasks span. A member already standing
  by its agent is in place.
- At the task (`enclose`): m places evenly spaced round it, the ring turned so that the group's
  side faces where it comes from, and members matched to places by the least total distance
  (`assign`, the Hungarian method).

Pure and deterministic: every tie is broken by id or index, so every robot computes the same places.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from functools import lru_cache

Point = tuple[float, float]
ANGLES = 12  # places tried on the first ring; wider rings get more, about as far apart
RINGS = 6  # rings tried before a member is given its nearest place, free or not


def radius(members: int, spacing: float, gap: float) -> float:
    """The ring round an agent or a task: `spacing`, or wider when the members would stand closer
    than `gap` to each other on it."""
    return max(spacing, members * gap / (2.0 * math.pi))


def on_ring(centre: Point, r: float, angle: float) -> Point:
    return (centre[0] + r * math.cos(angle), centre[1] + r * math.sin(angle))


def assign(costs: Sequence[Sequence[float]]) -> list[int]:
    """The column of each row that makes the total cost least (rows <= columns): the Hungarian
    method with potentials, O(n²m). Ties go to the smaller index, so the answer is deterministic."""
    n = len(costs)
    m = len(costs[0]) if n else 0
    if n > m:
        raise ValueError(f"{n} rows cannot take distinct columns of {m}")
    u, v = [0.0] * (n + 1), [0.0] * (m + 1)
    owner = [0] * (m + 1)  # owner[j]: the row (1-based) holding column j; 0: free
    for i in range(1, n + 1):
        _add_row(costs, i, u, v, owner)
    out = [0] * n
    for j in range(1, m + 1):
        if owner[j]:
            out[owner[j] - 1] = j - 1
    return out


def _add_row(costs: Sequence[Sequence[float]], i: int, u: list[float], v: list[float],
             owner: list[int]) -> None:
    """One step of `assign`: row i takes a column along the cheapest augmenting path."""
    m = len(v) - 1
    owner[0], j0 = i, 0
    low, way, used = [math.inf] * (m + 1), [0] * (m + 1), [False] * (m + 1)
    while owner[j0] != 0:
        used[j0] = True
        i0, delta, j1 = owner[j0], math.inf, 0
        for j in range(1, m + 1):
            if used[j]:
                continue
            cur = costs[i0 - 1][j - 1] - u[i0] - v[j]
            if cur < low[j]:
                low[j], way[j] = cur, j0
            if low[j] < delta:
                delta, j1 = low[j], j
        for j in range(m + 1):
            if used[j]:
                u[owner[j]] += delta
                v[j] -= delta
            else:
                low[j] -= delta
        j0 = j1
    while j0:
        j1 = way[j0]
        owner[j0] = owner[j1]
        j0 = j1


def enclose(task: Point, members: Sequence[str], where: Mapping[str, Point], spacing: float,
            gap: float, came_from: Point, bounds: tuple[Point, Point] | None = None) -> dict[str, Point]:
    """Each member's place round the task: m places evenly spaced, the ring turned so that the
    members split either side of the way from `came_from` (or turned the least from that so that
    as few places as can be lie outside `bounds`: a task by a wall), each member on the place that
    makes the group's total walk least."""
    m = len(members)
    if m == 0:
        return {}
    r = radius(m, spacing, gap)
    back = math.atan2(came_from[1] - task[1], came_from[0] - task[0])
    preferred = back + math.pi / m if m > 1 else back

    def ring_at(turn: float) -> list[Point]:
        return [on_ring(task, r, preferred + turn + 2.0 * math.pi * k / m) for k in range(m)]

    def outside(places: list[Point]) -> int:
        if bounds is None:
            return 0
        (x0, y0), (x1, y1) = bounds
        e = r / 4.0  # a place a little beyond the box is no nearer a wall than the task is
        return sum(not (x0 - e <= x <= x1 + e and y0 - e <= y <= y1 + e) for x, y in places)

    turns = sorted((2.0 * math.pi * k / ANGLES / 2.0 * sign for k in range(ANGLES) for sign in (1, -1)),
                   key=abs)
    places = min((ring_at(t) for t in turns), key=outside)  # min keeps the first: the least turn
    costs = [[math.dist(where[a], p) for p in places] for a in members]
    return {a: places[k] for a, k in zip(members, assign(costs), strict=True)}


Groups = tuple[tuple[str, tuple[str, ...]], ...]
Starts = tuple[tuple[str, float, float], ...]


def form_places(groups: Sequence[tuple[str, Sequence[str]]], starts: Mapping[str, Point],
                bounds: tuple[Point, Point], spacing: float, gap: float) -> dict[str, Point]:
    """Every robot's place when its group has formed up: each agent's start, and for each member a
    free place on rings round its agent (see the module's doc). `groups` are (agent, members)."""
    key_groups = tuple((a, tuple(sorted(ms))) for a, ms in groups)
    key_starts = tuple(sorted((r, float(p[0]), float(p[1])) for r, p in starts.items()))
    return dict(_form_places(key_groups, key_starts, bounds, float(spacing), float(gap)))


@lru_cache(maxsize=16)
def _form_places(groups: Groups, starts: Starts, bounds: tuple[Point, Point], spacing: float,
                 gap: float) -> tuple[tuple[str, Point], ...]:
    where = {r: (x, y) for r, x, y in starts}
    (x0, y0), (x1, y1) = bounds
    taken: dict[str, Point] = {a: where[a] for a, _ in groups}
    todo = {m: a for a, ms in groups for m in ms if m != a}
    size = {a: len(ms) - 1 for a, ms in groups}
    for ring in range(RINGS):
        choices = []
        for member, agent in todo.items():
            r = radius(size[agent], spacing, gap) + ring * gap
            count = max(ANGLES, math.ceil(2.0 * math.pi * r / (gap / 2.0)))
            for k in range(count):
                p = on_ring(where[agent], r, 2.0 * math.pi * k / count)
                if x0 <= p[0] <= x1 and y0 <= p[1] <= y1:
                    choices.append((math.dist(where[member], p), member, k, p))
        for _cost, member, _k, p in sorted(choices):
            if member in todo and all(math.dist(p, q) >= gap for q in taken.values()):
                taken[member] = p
                del todo[member]
        if not todo:
            break
    for member, agent in sorted(todo.items()):  # no free place anywhere near: the nearest ring place
        taken[member] = on_ring(where[agent], spacing, math.atan2(where[member][1] - where[agent][1],
                                                                   where[member][0] - where[agent][0]))
    return tuple(sorted((r, (round(p[0], 6), round(p[1], 6))) for r, p in taken.items()))
