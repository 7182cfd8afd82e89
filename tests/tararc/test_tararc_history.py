"""The collaboration history: updates after a run, the file round-trip, errors at their place."""

from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from hfsm_behaviours.tararc.history import History, Record, p_term, record_run, relevance_matrix
from hfsm_behaviours.tararc.history_file import HistoryError, dumps, load, loads, save


def test_record_run_counts_pairs_and_robots() -> None:
    h = record_run(History(), [("r1", "r0"), ("r2", "r3", "r4")], [True, False], {"r0": 0.6})
    assert h.pairs == {("r0", "r1"): Record(1, 0), ("r2", "r3"): Record(0, 1),
                       ("r2", "r4"): Record(0, 1), ("r3", "r4"): Record(0, 1)}
    assert h.robots == {"r0": Record(1, 0), "r1": Record(1, 0), "r2": Record(0, 1),
                        "r3": Record(0, 1), "r4": Record(0, 1)}
    assert h.beliefs == {"r0": 0.6}
    # R: r0-r1 has n_s = 1, S = 1 -> 1.0; the failed pairs have n_s = 0 -> 0, left out
    assert relevance_matrix(h) == {("r0", "r1"): 1.0}


def test_groups_learn_over_runs() -> None:
    h = History()
    for ok in (True, False, True, True):
        h = record_run(h, [("a", "b")], [ok])
    # n_s = 3, n_f = 1: R = 0.75 ** (1/3) = 0.9086; P_a^beta is the same from a's own record
    assert h.pair_record("b", "a") == Record(3, 1)
    assert relevance_matrix(h)[("a", "b")] == pytest.approx(0.9085602964160698)
    assert p_term(h, "a") == pytest.approx(0.9085602964160698)
    assert p_term(h, "nobody") == 0.0


def test_record_run_rejects_a_robot_in_two_groups() -> None:
    with pytest.raises(ValueError, match="two groups"):
        record_run(History(), [("a", "b"), ("b", "c")], [True, True])


ids = st.sampled_from([f"r{i}" for i in range(8)])
records = st.builds(Record, st.integers(0, 40), st.integers(0, 40))
histories = st.builds(
    History,
    pairs=st.dictionaries(st.tuples(ids, ids).filter(lambda p: p[0] < p[1]), records),
    robots=st.dictionaries(ids, records),
    beliefs=st.dictionaries(ids, st.floats(-10, 10, allow_nan=False, allow_subnormal=True)),
)


@given(histories)
def test_the_file_round_trips(h: History) -> None:
    text = dumps(h)
    assert loads(text) == h
    assert dumps(loads(text)) == text  # written sorted: the same history, the same bytes


def test_an_empty_record_is_no_record() -> None:
    assert History(robots={"a": Record()}, pairs={("a", "b"): Record()}) == History()


def test_save_and_load(tmp_path: Path) -> None:
    h = record_run(History(), [("r0", "r1")], [True], {"r0": 1e-05, "r1": 0.52})
    save(tmp_path / "h.json", h)
    assert load(tmp_path / "h.json") == h


def test_a_syntax_error_has_its_position() -> None:
    with pytest.raises(HistoryError) as err:
        loads('{"version": 1,\n "pairs": [\n}', "h.json")
    assert err.value.errors[0].startswith("h.json:3:1: not valid JSON")


def test_all_schema_errors_at_once_with_positions() -> None:
    # each position is the first character of the bad value (or key, or entry)
    text = (
        '{"version": 1,\n'
        ' "pairs": [{"robots": ["r0", "r0"], "n_s": 1, "n_f": 0},\n'
        '           {"robots": ["r0", "r1"], "n_s": -1, "n_f": 0}],\n'
        ' "robots": [{"id": "r0", "n_s": 1, "n_f": 0, "belif": 0.5},\n'
        '            {"id": "r1", "n_s": "2", "n_f": 0, "belief": "high"}]}\n'
    )
    with pytest.raises(HistoryError) as err:
        loads(text, "h.json")
    assert err.value.errors == [
        "h.json:2:23: a pair names two different robots",
        "h.json:3:44: expected a whole number >= 0",
        "h.json:4:46: unknown field 'belif'; did you mean 'belief'?",
        "h.json:5:33: expected a whole number >= 0",
        "h.json:5:58: expected a finite number",
    ]


def test_version_duplicates_and_missing_fields() -> None:
    text = '{"version": 2, "robots": [{"id": "a", "n_s": 0, "n_f": 0}, {"id": "a", "n_s": 1, "n_f": 0}, {"id": "b"}]}'
    with pytest.raises(HistoryError) as err:
        loads(text, "h.json")
    assert err.value.errors == [
        "h.json:1:13: unknown history version 2 (this reader knows 1)",
        "h.json:1:60: robot a appears twice",
        "h.json:1:93: missing field 'n_f'",
        "h.json:1:93: missing field 'n_s'",
    ]


@pytest.mark.parametrize("text", ["", "[]", '"x"'])
def test_not_an_object(text: str) -> None:
    with pytest.raises(HistoryError, match=r"h\.json:1:1"):
        loads(text, "h.json")


def test_an_unreadable_file(tmp_path: Path) -> None:
    with pytest.raises(HistoryError, match="cannot read"):
        load(tmp_path / "missing.json")


def test_save_never_leaves_half_a_file(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import os

    path = tmp_path / "h.json"
    old = record_run(History(), [("r0", "r1")], [True])
    save(path, old)
    before = path.read_bytes()

    def crash(*_: object) -> None:
        raise OSError("disk full")

    monkeypatch.setattr(os, "replace", crash)
    with pytest.raises(OSError, match="disk full"):
        save(path, record_run(old, [("r0", "r1")], [False]))
    assert path.read_bytes() == before and sorted(p.name for p in tmp_path.iterdir()) == ["h.json"]


def test_save_keeps_the_files_permissions(tmp_path: Path) -> None:
    path = tmp_path / "h.json"
    save(path, History())
    assert path.stat().st_mode & 0o777 == 0o644
    path.chmod(0o600)
    save(path, record_run(History(), [("r0", "r1")], [True]))
    assert path.stat().st_mode & 0o777 == 0o600


def test_problems_before_a_run(tmp_path: Path) -> None:
    from hfsm_behaviours.tararc.history_file import problems

    assert problems("") == [] and problems(str(tmp_path / "first.json")) == []
    assert problems(str(tmp_path / "no" / "h.json"))[0][:3] == (str(tmp_path / "no" / "h.json"), 1, 1)
    (tmp_path / "h.json").write_text('{"version": 1, "robots": [{"id": "r0"}]}', encoding="utf-8")
    assert problems(str(tmp_path / "h.json")) == [
        (str(tmp_path / "h.json"), 1, 27, "missing field 'n_f'"),
        (str(tmp_path / "h.json"), 1, 27, "missing field 'n_s'"),
    ]
