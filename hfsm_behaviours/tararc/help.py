"""Help strategies on node failure (TARARC section 4.3 step 7) as pure decisions."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from hfsm_behaviours.tararc.grouping import Group, Robot, distance


@dataclass(frozen=True)
class HandOver:
    """7a: `old` leaves the group, `new` becomes its agent and moves to `old`'s position."""

    old: str
    new: str
    group: Group


def hand_over(
    group: Group, agent_energy: float, s_thres: float, beliefs: Mapping[str, float]
) -> HandOver | None:
    """7a: an agent with S_j < S_thres hands over to the member with the highest F (ties by id).

    None when the agent's energy is enough, or when it has no member left to take over. The old
    agent is removed from the group ("deleted from the robot list"); the others keep their order.
    """
    if agent_energy >= s_thres:
        return None
    others = [m for m in group.members if m != group.agent]
    if not others:
        return None
    new = min(others, key=lambda m: (-beliefs[m], m))
    return HandOver(group.agent, new, Group(new, tuple(others)))


@dataclass(frozen=True)
class Transfer:
    """7b: `member` leaves group `giver` (an index) for group `taker`."""

    member: str
    giver: int
    taker: int


def lend(groups: Sequence[Group], needy: int, n_thres: int, robots: Mapping[str, Robot],
         keep: int = 1) -> list[Transfer]:
    """7b: while group `needy` has fewer than n_thres robots, the other groups, nearest agent first
    (distance between agents, ties by group index), each give one member in turn.

    A giver gives the non-agent member nearest the needy agent (ties by id) and never drops below
    n_thres itself (the paper does not say; otherwise help would only move the shortage). With
    `keep` > 1 it also keeps its first keep - 1 members besides its agent (a room's pair at work
    lends only its spares). Returns the transfers in order; fewer than needed when no group can
    spare a robot.
    """
    if n_thres < 1:
        raise ValueError(f"n_thres must be >= 1, got {n_thres}")
    if keep < 1:
        raise ValueError(f"keep must be >= 1, got {keep}")
    sizes = [len(g.members) for g in groups]
    given: list[set[str]] = [set() for _ in groups]
    target = robots[groups[needy].agent]
    givers = sorted(
        (i for i in range(len(groups)) if i != needy),
        key=lambda i: (distance(robots[groups[i].agent], target), i),
    )
    out: list[Transfer] = []
    while sizes[needy] < n_thres:
        gave = False
        for i in givers:
            if sizes[needy] >= n_thres:
                break
            others = [m for m in groups[i].members if m != groups[i].agent]
            spare = [m for m in others[keep - 1:] if m not in given[i]]
            if sizes[i] <= n_thres or not spare:
                continue
            member = min(spare, key=lambda m: (distance(robots[m], target), m))
            given[i].add(member)
            sizes[i] -= 1
            sizes[needy] += 1
            out.append(Transfer(member, i, needy))
            gave = True
        if not gave:
            break
    return out


def apply_transfers(groups: Sequence[Group], transfers: Sequence[Transfer]) -> list[Group]:
    """The groups after the transfers: each member appended to its taker, in transfer order."""
    out = list(groups)
    for t in transfers:
        giver = out[t.giver]
        out[t.giver] = Group(giver.agent, tuple(m for m in giver.members if m != t.member))
        taker = out[t.taker]
        out[t.taker] = Group(taker.agent, (*taker.members, t.member))
    return out
