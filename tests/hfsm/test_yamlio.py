from __future__ import annotations

import contextlib
import os
from pathlib import Path

import pytest
import yaml
from hypothesis import given
from hypothesis import strategies as st

from hfsm import yamlio
from hfsm.errors import UserError
from hfsm.yamlio import MAX_BYTES, MAX_DEPTH, decode, parse_text, read_file


def codes(text: str) -> list[str]:
    with pytest.raises(UserError) as info:
        parse_text(text, "f.yaml")
    return [f.code for f in info.value.findings]


def test_yaml_1_1_booleans_stay_strings() -> None:
    doc = parse_text("on: yes\noff: no\ny: n\nt: true\n", "f.yaml")
    assert doc.data == {"on": "yes", "off": "no", "y": "n", "t": True}


def test_core_schema_scalars() -> None:
    doc = parse_text("a: [1, -2, 0x1f, 0o17, 1.5, 1e3, ~, null, '', 1_000, 2001-01-01]\n", "f.yaml")
    assert doc.data["a"][:8] == [1, -2, 31, 15, 1.5, 1000.0, None, None]
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


def first(text: str) -> tuple[int, int, str, str]:
    with pytest.raises(UserError) as info:
        parse_text(text, "f.yaml")
    f = info.value.findings[0]
    return f.line, f.col, f.code, f.message


class _StrictParser(yamlio._PyParser):
    """A parser with a flow nesting limit of its own just above ours, as newer libyaml has (1,000)."""

    def __init__(self, text: str) -> None:
        if text.count("[") > MAX_DEPTH + 10:
            mark = yaml.Mark("f.yaml", MAX_DEPTH + 13, 0, MAX_DEPTH + 13, None, None)
            raise yaml.parser.ParserError(None, None, "exceeded max depth of 110", mark)
        super().__init__(text)


PARSERS = {"installed": yamlio._Parser, "pure Python": yamlio._PyParser, "strict": _StrictParser}


@pytest.mark.parametrize("parser", PARSERS)
@pytest.mark.parametrize("depth", [150, 1_001, 100_000])
def test_any_flow_nesting_depth_is_a_positioned_error(depth: int, parser: str,
                                                       monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(yamlio, "_Parser", PARSERS[parser])
    line, col, code, message = first("a: " + "[" * depth + "]" * depth + "\n")
    assert (line, col, code) == (1, 4 + MAX_DEPTH - 1, "E106")
    assert f"{MAX_DEPTH} deep" in message


@given(st.integers(1, 3), st.integers(MAX_DEPTH - 3, 5_000), st.sampled_from("[{"))
def test_brackets_inside_blocks_past_the_limit_are_a_positioned_error(blocks: int, depth: int,
                                                                      bracket: str) -> None:
    head = "".join(" " * i + f"k{i}:\n" for i in range(blocks))
    inner = "[1]" if bracket == "[" else "{a: 1}"
    opens = "".join(bracket if bracket == "[" else "{b: " for _ in range(depth))
    closes = ("]" if bracket == "[" else "}") * depth
    text = head + " " * blocks + opens + inner + closes + "\n"
    if blocks + depth + 1 <= MAX_DEPTH:
        parse_text(text, "f.yaml")
        return
    line, col, code, _ = first(text)
    assert (line, code) == (blocks + 1, "E106")
    width = 1 if bracket == "[" else len("{b: ")
    assert col == blocks + 1 + (MAX_DEPTH - blocks) * width  # the collection one past the limit


def test_brackets_in_quotes_and_comments_do_not_count() -> None:
    text = "a: '" + "[" * 300 + "'  # " + "{" * 300 + "\nb: \"" + "[" * 300 + "\"\n"
    assert parse_text(text, "f.yaml").data["a"] == "[" * 300


def test_deep_block_nesting_is_a_positioned_error() -> None:
    text = "".join(" " * i + f"k{i}:\n" for i in range(MAX_DEPTH + 5)) + " " * (MAX_DEPTH + 5) + "x\n"
    line, _, code, _ = first(text)
    assert (line, code) == (MAX_DEPTH + 1, "E106")  # the top mapping is level 1


def test_nesting_up_to_the_limit_is_read() -> None:
    depth = MAX_DEPTH - 1
    value = parse_text("a: " + "[" * depth + "]" * depth + "\n", "f.yaml").data["a"]
    for _ in range(depth - 1):
        (value,) = value
    assert value == []


def test_many_plain_nodes_are_not_an_alias_bomb() -> None:
    doc = parse_text("a: [" + "1, " * 250_000 + "2]\n", "f.yaml")
    assert len(doc.data["a"]) == 250_001


def test_aliases_repeat_their_anchor_with_its_positions() -> None:
    doc = parse_text("a: &x {b: [1, 2]}\nc: *x\n", "f.yaml")
    assert doc.data == {"a": {"b": [1, 2]}, "c": {"b": [1, 2]}}
    assert doc.values[("c", "b", 1)] == doc.values[("a", "b", 1)] == (1, 15)


def test_a_redefined_anchor_keeps_what_it_named_before() -> None:
    doc = parse_text("a: &x [1]\nb: &x [*x, 2]\nc: *x\nd: &s v\ne: *s\n", "f.yaml")
    assert doc.data == {"a": [1], "b": [[1], 2], "c": [[1], 2], "d": "v", "e": "v"}


@pytest.mark.parametrize("text", ["a: &x [*x]\n", "a: *x\nb: &x 1\n"])
def test_an_alias_before_its_anchor_is_an_error(text: str) -> None:
    assert first(text)[2] == "E100"


def test_chained_aliases_expand_without_recursion() -> None:
    n = MAX_DEPTH - 2
    lines = ["a0: &a0 [1]"] + [f"a{i}: &a{i} [*a{i - 1}]" for i in range(1, n + 1)]
    doc = parse_text("\n".join(lines) + "\n", "f.yaml")
    value = doc.data[f"a{n}"]
    for _ in range(n):
        value = value[0]
    assert value == [1]


@pytest.mark.parametrize("literal", [".nan", ".NaN", ".inf", "-.inf", "+.Inf", "1e999", "!!float .nan"])
def test_non_finite_numbers_are_refused(literal: str) -> None:
    line, col, code, message = first(f"a:\n  b: {literal}\n")
    assert (line, col, code) == (2, 6, "E100")
    assert "finite" in message


def test_a_second_document_is_pointed_at() -> None:
    assert first("a: 1\n---\nb: 2\n")[:3] == (2, 1, "E100")


@pytest.mark.parametrize(
    ("text", "words"),
    [
        ("a:\n\tb: 1\n", "a tab"),
        ("a: x\n\tb: 2\n", "a tab"),
        ("states:\n  s:\n    do: log\n     with: 1\n", "indented deeper than line 3"),
        ("text: hello: world\n", "quote a value that holds ': '"),
        ("a:\n  b: 1\n c: 2\n", "does not line up"),
        ("a: [x, #y]\n", "'#'"),
        ("a: @x\n", "'@' cannot start"),
        ('a: "x\n', "never closed"),
    ],
)
def test_syntax_errors_carry_a_hint(text: str, words: str) -> None:
    assert words in first(text)[3]


def test_a_fifo_is_refused_at_once(tmp_path: Path) -> None:
    fifo = tmp_path / "m.yaml"
    os.mkfifo(fifo)
    with pytest.raises(UserError) as info:
        read_file(fifo)
    assert "not a regular file" in str(info.value)


def test_a_device_and_a_folder_are_refused(tmp_path: Path) -> None:
    for path, words in ((Path("/dev/zero"), "not a regular file"), (tmp_path, "a folder")):
        with pytest.raises(UserError) as info:
            read_file(path)
        assert words in str(info.value)


def test_a_huge_file_is_refused_unread(tmp_path: Path) -> None:
    big = tmp_path / "big.yaml"
    with big.open("wb") as f:
        f.truncate(MAX_BYTES + 1)  # sparse: nothing is read, nothing much written
    with pytest.raises(UserError) as info:
        read_file(big)
    assert info.value.findings[0].code == "E106"
