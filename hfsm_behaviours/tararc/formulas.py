"""TARARC's numbers (Han et al., section 4.3, eqs. 1-5), with the paper's gaps closed.

Every function is pure: the same arguments give the same float on every robot. How each gap of the
paper is closed is written here and in docs/TARARC.md ("Formulas and the paper's gaps").
"""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(frozen=True)
class Coefficients:
    """The paper's constants, with its values as defaults (section 5.1: k1..k5 = 0.2, l1 = l2 = 0.05)."""

    k1: float = 0.2
    k2: float = 0.2
    k3: float = 0.2
    k4: float = 0.2
    k5: float = 0.2
    l1: float = 0.05
    l2: float = 0.05


@dataclass(frozen=True)
class EnergyModel:
    """Eq. 5's weights and (negative) exponents; the paper gives neither, so these are ours.

    Weights sum to 1 as the paper requires. With exponents -0.5 each term halves when its argument
    reaches 3 (readings, metres, m/s); a scenario can steepen it.
    """

    w_tim: float = 1 / 3
    w_dist: float = 1 / 3
    w_sped: float = 1 / 3
    m: float = -0.5
    n: float = -0.5
    t: float = -0.5

    def __post_init__(self) -> None:
        if not math.isclose(self.w_tim + self.w_dist + self.w_sped, 1.0, abs_tol=1e-9):
            raise ValueError("energy weights must sum to 1 (eq. 5)")
        if min(self.w_tim, self.w_dist, self.w_sped) < 0:
            raise ValueError("energy weights must not be negative")
        if max(self.m, self.n, self.t) >= 0:
            raise ValueError("energy exponents m, n, t must be negative (eq. 5)")


PAPER = Coefficients()
DEFAULT_ENERGY = EnergyModel()


def success_rate(n_s: int, n_f: int) -> float:
    """Eq. 2: S = n_s / (n_s + n_f); 0 when there is no collaboration at all."""
    _counts(n_s, n_f)
    total = n_s + n_f
    return n_s / total if total else 0.0


def powered_rate(n_s: int, n_f: int) -> float:
    """S^beta with beta = 1/n_s (eq. 1), the term shared by relevance and belief.

    At n_s = 0 the paper's beta is undefined. We take the limit S^(1/n_s) for S -> 0, n_s -> 0+,
    which is 0: a pair (or robot) with no success has no earned trust, however many failures.
    """
    _counts(n_s, n_f)
    if n_s == 0:
        return 0.0
    return float(success_rate(n_s, n_f) ** (1.0 / n_s))


def relevance(n_s: int, n_f: int) -> float:
    """Eq. 1: R_ij = C_ij * S_ij^beta, with C_ij = 1 exactly when the pair ever worked together.

    C_ij is read from the counts (n_s + n_f > 0), so it cannot disagree with them.
    """
    collaborated = 1.0 if n_s + n_f > 0 else 0.0
    return collaborated * powered_rate(n_s, n_f)


def belief(
    p_term: float,
    difficulty: float,
    energy: float,
    order: int,
    coeff: Coefficients = PAPER,
) -> float:
    """Eq. 3: F = (k1 + k2*P_j^beta + k3*d_t + k4*S_t) / (k5*j_ord + 1).

    - P_j^beta (`p_term`): the paper never defines P_j. We take the robot's own task record,
      P_j = its successful tasks / its tasks, with beta = 1/(its successful tasks) as in eq. 1:
      pass `powered_rate(tasks_ok, tasks_failed)`. F thus rises after a success and falls after a
      failure, as the paper says, with no step size to invent.
    - d_t (`difficulty`): the task's difficulty. Before allocation (agent election) there is no
      task yet; callers pass the mean difficulty of the task set, the same for every robot, so the
      election is decided by the other terms (see `election_difficulty`).
    - S_t (`energy`): the robot's residual energy S_j of eq. 5, in [0, 1].
    - j_ord (`order`): the robot's place in its group, 0 for the group's seed (see grouping).
    """
    if order < 0:
        raise ValueError(f"order must be >= 0, got {order}")
    numerator = coeff.k1 + coeff.k2 * p_term + coeff.k3 * difficulty + coeff.k4 * energy
    return numerator / (coeff.k5 * order + 1.0)


def election_difficulty(difficulties: list[float]) -> float:
    """The d_t used for F before any task is allocated: the mean difficulty of the task set."""
    if not difficulties:
        raise ValueError("no tasks: the election needs at least one task")
    return math.fsum(difficulties) / len(difficulties)


def cost(distance: float, difficulty: float, coeff: Coefficients = PAPER) -> float:
    """C = l1*sqrt(d_it) + l2*d_t (eq. 4's cost); d_t in (0, 1) as the paper requires, so C > 0."""
    if distance < 0:
        raise ValueError(f"distance must be >= 0, got {distance}")
    check_difficulty(difficulty)
    return coeff.l1 * math.sqrt(distance) + coeff.l2 * difficulty


def efficiency(f: float, distance: float, difficulty: float, coeff: Coefficients = PAPER) -> float:
    """Eq. 4: B = F / C."""
    return f / cost(distance, difficulty, coeff)


def energy(tim: float, dist: float, sped: float, model: EnergyModel = DEFAULT_ENERGY) -> float:
    """Eq. 5, bounded: S_j = w1*(1+tim)^m + w2*(1+dist)^n + w3*(1+sped)^t, in (0, 1].

    The paper's x^m (m < 0) is infinite at x = 0 and above 1 for x < 1, so a fresh robot would
    have unbounded energy, against its own claim S_j in [0, 1]. Shifting each argument by 1 is the
    smallest change that keeps the paper's shape (decreasing, the same power-law tail) and makes a
    fresh robot exactly full: S_j = 1 at tim = dist = sped = 0, and S_j -> 0 as any grows.
    """
    if min(tim, dist, sped) < 0:
        raise ValueError("tim, dist and sped must be >= 0")
    terms = ((model.w_tim, tim, model.m), (model.w_dist, dist, model.n), (model.w_sped, sped, model.t))
    return math.fsum(w * math.pow(1.0 + x, e) for w, x, e in terms)


def check_difficulty(difficulty: float) -> None:
    """The paper's d_t lies in the open interval (0, 1)."""
    if not 0.0 < difficulty < 1.0:
        raise ValueError(f"difficulty must be in (0, 1), got {difficulty}")


def _counts(n_s: int, n_f: int) -> None:
    if n_s < 0 or n_f < 0:
        raise ValueError(f"collaboration counts must be >= 0, got n_s={n_s}, n_f={n_f}")
