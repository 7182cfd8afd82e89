"""TARARC eqs. 1-5 against values computed by hand (the arithmetic is in each test)."""

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from hfsm_behaviours.tararc.formulas import (
    Coefficients,
    EnergyModel,
    belief,
    cost,
    efficiency,
    election_difficulty,
    energy,
    powered_rate,
    relevance,
    success_rate,
)


def test_success_rate_is_eq_2() -> None:
    assert success_rate(3, 1) == 3 / 4
    assert success_rate(0, 0) == 0.0
    assert success_rate(0, 5) == 0.0


def test_relevance_is_eq_1() -> None:
    # n_s = 1, n_f = 1: S = 1/2, beta = 1/1, R = 0.5
    assert relevance(1, 1) == 0.5
    # n_s = 2, n_f = 2: S = 1/2, beta = 1/2, R = sqrt(0.5) = 0.70710678...
    assert relevance(2, 2) == pytest.approx(0.7071067811865476)
    # n_s = 3, n_f = 1: S = 3/4, beta = 1/3, R = 0.75 ** (1/3) = 0.9085602964...
    assert relevance(3, 1) == pytest.approx(0.9085602964160698)
    # always successful: S = 1, R = 1 whatever n_s
    assert relevance(7, 0) == 1.0


def test_relevance_without_success_is_zero() -> None:
    assert relevance(0, 0) == 0.0  # never worked together: C_ij = 0
    assert relevance(0, 4) == 0.0  # n_s = 0: beta undefined, limit of S^(1/n_s) is 0
    assert powered_rate(0, 4) == 0.0


def test_counts_must_not_be_negative() -> None:
    with pytest.raises(ValueError, match="counts"):
        relevance(-1, 0)


def test_belief_is_eq_3() -> None:
    # (0.2 + 0.2*0.5 + 0.2*0.5 + 0.2*1.0) / (0.2*0 + 1) = (0.2 + 0.1 + 0.1 + 0.2) / 1 = 0.6
    assert belief(0.5, 0.5, 1.0, 0) == pytest.approx(0.6)
    # same numerator at j_ord = 2: 0.6 / (0.2*2 + 1) = 0.6 / 1.4 = 0.428571...
    assert belief(0.5, 0.5, 1.0, 2) == pytest.approx(0.6 / 1.4)
    # other coefficients: (1 + 2*0.25 + 3*0.4 + 4*0.5) / (5*1 + 1) = (1 + 0.5 + 1.2 + 2) / 6 = 4.7 / 6
    k = Coefficients(k1=1, k2=2, k3=3, k4=4, k5=5)
    assert belief(0.25, 0.4, 0.5, 1, k) == pytest.approx(4.7 / 6)


def test_cost_and_efficiency_are_eq_4() -> None:
    # C = 0.05*sqrt(4) + 0.05*0.5 = 0.1 + 0.025 = 0.125
    assert cost(4.0, 0.5) == pytest.approx(0.125)
    # B = F / C = 0.6 / 0.125 = 4.8
    assert efficiency(0.6, 4.0, 0.5) == pytest.approx(4.8)
    # at the task: C = 0.05*0.5 = 0.025 > 0, B = 0.6 / 0.025 = 24
    assert efficiency(0.6, 0.0, 0.5) == pytest.approx(24.0)


@pytest.mark.parametrize("difficulty", [0.0, 1.0, -0.1, 1.5])
def test_difficulty_is_in_the_open_unit_interval(difficulty: float) -> None:
    with pytest.raises(ValueError, match="difficulty"):
        cost(1.0, difficulty)


def test_energy_is_eq_5_shifted() -> None:
    assert energy(0, 0, 0) == pytest.approx(1.0)  # a fresh robot is full
    # each term (1 + 3) ** -0.5 = 1/2: S = 1/3 * (1/2 + 1/2 + 1/2) = 1/2
    assert energy(3, 3, 3) == pytest.approx(0.5)
    # 1/3 * ((1+3)**-0.5 + (1+0)**-0.5 + (1+8)**-0.5) = 1/3 * (1/2 + 1 + 1/3) = 11/18
    assert energy(3, 0, 8) == pytest.approx(11 / 18)


def test_energy_model_follows_the_paper_constraints() -> None:
    with pytest.raises(ValueError, match="sum to 1"):
        EnergyModel(w_tim=0.5, w_dist=0.5, w_sped=0.5)
    with pytest.raises(ValueError, match="negative"):
        EnergyModel(m=0.5)


@given(
    st.floats(0, 1e9, allow_nan=False),
    st.floats(0, 1e9, allow_nan=False),
    st.floats(0, 1e9, allow_nan=False),
    st.floats(0, 1e3, allow_nan=False),
)
def test_energy_is_bounded_and_decreasing(tim: float, dist: float, sped: float, more: float) -> None:
    s = energy(tim, dist, sped)
    assert 0.0 < s <= 1.0 + 1e-12
    assert energy(tim + more, dist, sped) <= s
    assert energy(tim, dist + more, sped) <= s


@given(st.integers(0, 50), st.integers(0, 50))
def test_relevance_is_in_the_unit_interval(n_s: int, n_f: int) -> None:
    assert 0.0 <= relevance(n_s, n_f) <= 1.0


def test_election_difficulty_is_the_mean() -> None:
    # (0.2 + 0.5 + 0.9) / 3 = 1.6 / 3
    assert election_difficulty([0.2, 0.5, 0.9]) == pytest.approx(1.6 / 3)
    assert math.isclose(election_difficulty([0.3]), 0.3)
    with pytest.raises(ValueError):
        election_difficulty([])
