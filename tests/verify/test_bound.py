"""The search's bound: `--bound`, else the top machine's timer, a number or an expression over
params worked out with the run's params, else 600 s."""

from __future__ import annotations

from pathlib import Path

import pytest
from verify_run import verify

from hfsm.load import load
from hfsm.verify.build import DEFAULT_BOUND, bound_of

LAPS = """\
params:
  limit: {type: float, default: 3}
  laps: {type: int, default: 1}
timer: ${TIMER}
outcomes: [done]
states:
  lap:
    do: wait
    with: {seconds: 1}
    on: {done: again}
  again:
    choose:
      - if: "params.laps == 0"
        then: done
      - else: lap
"""


def _top(tmp_path: Path, timer: str) -> object:
    file = tmp_path / "laps.yaml"
    file.write_text(LAPS.replace("${TIMER}", f'"{timer}"' if timer.startswith("$") else timer))
    return load([file]).roots[0]


@pytest.mark.parametrize(
    ("timer", "params", "bound"),
    [
        ("${params.limit}", {"a": {}}, 3.0),
        ("${params.limit}", {"a": {"limit": 7.5}}, 7.5),
        ("${params.limit * 2}", {"a": {"limit": 1.0}, "b": {"limit": 4.0}}, 8.0),  # the longest agent's
        ("${params.limit * (2 if agent.id == 'b' else 1)}", {"a": {}, "b": {}}, 6.0),
        ("${params.limit - 3}", {"a": {}}, DEFAULT_BOUND),  # not positive: the run says so, not the bound
        ("${params.limit / params.laps}", {"a": {"laps": 0}}, DEFAULT_BOUND),  # an error at run time
        (2.5, {"a": {}}, 2.5),
    ],
)
def test_the_bound_is_the_top_timer_worked_out_from_params(
    tmp_path: Path, timer: object, params: dict[str, dict[str, object]], bound: float
) -> None:
    top = _top(tmp_path, str(timer))
    assert bound_of(top, None, params) == bound
    assert bound_of(top, 1.5, params) == 1.5


def test_a_search_of_a_machine_timed_by_a_param_stops_at_its_timer(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    file = tmp_path / "laps.yaml"
    file.write_text(LAPS.replace("${TIMER}", '"${params.limit}"'))
    code, verdict = verify(
        capsys, file, "--param", "limit=900", "--goal", "success", out=tmp_path / "ce.jsonl"
    )
    # its timer fires at 900 s: a timeout, not a run still going at a bound of 600 s
    assert (code, verdict["kind"]) == (1, "failure_outcome"), verdict["stderr"]
    assert "'timeout'" in verdict["stderr"]
