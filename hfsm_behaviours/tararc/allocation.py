"""Task competition (TARARC section 4.3 step 5): a sequential auction in priority order."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass

from hfsm_behaviours.tararc.formulas import PAPER, Coefficients, check_difficulty, efficiency
from hfsm_behaviours.tararc.grouping import Robot, distance


@dataclass(frozen=True)
class Task:
    """A sub-task: a place, a difficulty d_t in (0, 1), and a priority (smaller goes first)."""

    id: str
    x: float
    y: float
    difficulty: float
    priority: int

    def __post_init__(self) -> None:
        check_difficulty(self.difficulty)


BeliefAt = Callable[[str, float], float]
"""F of an agent for a task of the given difficulty d_t."""


def priority_order(tasks: Iterable[Task]) -> list[Task]:
    """Tasks by priority, ties by id."""
    return sorted(tasks, key=lambda t: (t.priority, t.id))


def bid(agent: Robot, task: Task, belief_at: BeliefAt, coeff: Coefficients = PAPER) -> float:
    """B = F / C of this agent for this task (eq. 4)."""
    where = Robot(task.id, task.x, task.y)
    return efficiency(belief_at(agent.id, task.difficulty), distance(agent, where), task.difficulty, coeff)


def compete(
    tasks: Iterable[Task],
    agents: Sequence[Robot],
    belief_at: BeliefAt,
    coeff: Coefficients = PAPER,
) -> list[tuple[str, str]]:
    """(task id, winning agent id) in priority order; each agent wins at most one task.

    For each task in turn, the agent not yet allocated with the highest B wins (ties by agent id).
    Tasks left when every agent has one stay unallocated (the paper merges tasks beforehand).
    """
    free = sorted(agents, key=lambda a: a.id)
    if len({a.id for a in free}) != len(free):
        raise ValueError("an agent appears twice")
    won: list[tuple[str, str]] = []
    for task in priority_order(tasks):
        if not free:
            break
        winner = min(free, key=lambda a: (-bid(a, task, belief_at, coeff), a.id))
        free.remove(winner)
        won.append((task.id, winner.id))
    return won
