from __future__ import annotations

import contextlib

import pytest
from hypothesis import given
from hypothesis import strategies as st

from hfsm.errors import UserError
from hfsm.yamlio import decode, parse_text


def codes(text: str) -> list[str]:
    with pytest.raises(UserError) as info:
        parse_text(text, "f.yaml")
    return [f.code for f in info.value.findings]


def test_yaml_1_1_booleans_stay_strings() -> None:
    doc = parse_text("on: yes\noff: no\ny: n\nt: true\n", "f.yaml")
    assert doc.data == {"on": "yes", "off": "no", "y": "n", "t": True}


def test_core_schema_scalars() -> None:
    doc = parse_text("a: [1, -2, 0x1f, 0o17, 1.5, .inf, ~, null, '', 1_000, 2001-01-01]\n", "f.yaml")
    assert doc.data["a"][:8] == [1, -2, 31, 15, 1.5, float("inf"), None, None]
    assert doc.data["a"][8:] == ["", "1_000", "2001-01-01"]


def test_positions_of_keys_and_values() -> None:
    doc = parse_text("a:\n  bb: [1, 2]\n", "f.yaml")
    assert doc.keys[("a", "bb")] == (2, 3)
    assert doc.values[("a", "bb", 1)] == (2, 11)


@pytest.mark.parametrize(
    ("text", "code"),
    [
        ("a: 1\na: 2\n", "E101"),
        ("a: !!python/object:os.system x\n", "E102"),
        ("a: !custom x\n", "E102"),
        ("a: &x {b: 1}\nc:\n  <<: *x\n", "E103"),
        ("", "E105"),
        ("# only a comment\n", "E105"),
        ("a: [\n", "E100"),
        ("a: b\n---\nc: d\n", "E100"),
        ("a: *nope\n", "E100"),
    ],
)
def test_rejected(text: str, code: str) -> None:
    assert code in codes(text)


def test_every_duplicate_reported_at_once() -> None:
    assert codes("a: 1\na: 2\nb: 1\nb: 2\n") == ["E101", "E101"]


def test_alias_bomb_rejected_fast() -> None:
    lines = ["a: &a [x, x, x, x, x, x, x, x, x]"]
    for i in range(1, 9):
        prev, name = chr(96 + i), chr(97 + i)
        lines.append(f"{name}: &{name} [" + ", ".join([f"*{prev}"] * 9) + "]")
    assert codes("\n".join(lines) + "\n") == ["E106"]


def test_non_utf8_reports_the_byte_position() -> None:
    with pytest.raises(UserError) as info:
        decode(b"a: 1\nb: \xff\n", "f.yaml")
    (finding,) = info.value.findings
    assert (finding.line, finding.col, finding.code) == (2, 4, "E104")


@given(st.binary(max_size=200))
def test_random_bytes_raise_only_user_errors(raw: bytes) -> None:
    with contextlib.suppress(UserError):
        parse_text(decode(raw, "f.yaml"), "f.yaml")
