"""The hostile classes of issue 19, generated from small to huge: integers where a float is needed,
mapping keys that are not strings, file names that are not machine names."""

from __future__ import annotations

import contextlib
import io
import json
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from hfsm.cli.run import main
from hfsm.errors import UserError
from hfsm.names import is_name
from hfsm.spec import fits_float
from hfsm.yamlio import parse_text

SETTINGS = settings(max_examples=25, deadline=None, suppress_health_check=list(HealthCheck))
DIGITS = st.integers(1, 4000).flatmap(lambda n: st.integers(10 ** (n - 1), 10**n - 1))
RUN = "outcomes: [done]\nstates:\n  a: {do: wait, with: {seconds: SECONDS}, on: {done: done}}\n"


def run(folder: Path, text: str, *args: str, name: str = "m.yaml") -> tuple[int, str]:
    path = folder / name
    path.write_text(text, encoding="utf-8")
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main([str(path), "--world", "none", "--quiet", "--json", *args])
    assert "Traceback" not in err.getvalue()
    return code, err.getvalue() + out.getvalue()


@SETTINGS
@given(DIGITS, st.sampled_from(["wait", "timer", "default", "param", "vars"]))
def test_an_integer_where_a_float_is_needed(tmp_path_factory: pytest.TempPathFactory, value: int,
                                              where: str) -> None:
    folder = tmp_path_factory.mktemp("f")
    text = RUN.replace("SECONDS", "1")
    args: list[str] = ["--max-time", "1"]
    if where == "wait":
        text = RUN.replace("SECONDS", str(value))
    elif where == "timer":
        text += f"timer: {value}\n"
    elif where in ("default", "param"):
        text = RUN.replace("SECONDS", "'${params.s}'") + f"params:\n  s: {{type: float, default: {value}}}\n"
        if where == "param":
            text = text.replace(f"default: {value}", "default: 1")
            args += ["--param", f"s={value}"]
    else:
        text = RUN.replace("SECONDS", "'${vars.s}'") + f"vars: {{s: {value}}}\n"
    code, said = run(folder, text, *args)
    if fits_float(value):
        assert code in (0, 1), said  # a long wait stops at --max-time
    elif where == "vars":  # known only as the run goes: an error of the run
        assert code == 1 and "too large for a float" in said, said
    else:
        assert code == 2 and "too large for a float" in said and ":" in said.split("error[")[0], said


KEYS = st.one_of(
    st.integers(-(10**30), 10**30).map(str),
    st.sampled_from(["null", "~", "true", "false", "1.5", ".inf", "-.inf", "0x1f"]),
    st.lists(st.sampled_from(["a", "1", "b"]), max_size=3).map(lambda k: "[" + ", ".join(k) + "]"),
    st.dictionaries(st.sampled_from(["a", "b"]), st.integers(0, 9), max_size=2).map(
        lambda d: "{" + ", ".join(f"{k}: {v}" for k, v in d.items()) + "}"),
)
PLACES = ["top", "states", "vars", "with", "on"]


@SETTINGS
@given(KEYS, st.sampled_from(PLACES), st.integers(0, 300))
def test_a_key_that_is_not_a_string_is_a_positioned_error(key: str, place: str, pad: int) -> None:
    lines = ["outcomes: [done]", "vars: {n: 0}", "states:", "  a:", "    do: wait", "    with:",
             "      seconds: 1", "    on:", "      done: done"]
    at = {"top": 1, "states": 3, "vars": 2, "with": 6, "on": 8}[place]
    indent = {"top": "", "states": "  ", "vars": "  ", "with": "      ", "on": "      "}[place]
    if place == "vars":
        lines[1] = "vars:"
    entry = f"{indent}? {key}\n{indent}: {'x' * pad or 'x'}"
    lines.insert(at, entry)
    with pytest.raises(UserError) as info:
        parse_text("\n".join(lines) + "\n", "f.yaml")
    finding = info.value.findings[0]
    assert (finding.line, finding.col, finding.code) == (at + 1, len(indent) + 3, "E100")
    assert "key must be" in finding.message or "not a finite number" in finding.message


@SETTINGS
@given(st.text(st.characters(blacklist_categories=("Cs",), blacklist_characters="/\x00"), min_size=1,
               max_size=120))
def test_a_file_name_that_is_not_a_machine_name_is_an_error_naming_it(
        tmp_path_factory: pytest.TempPathFactory, stem: str) -> None:
    if stem in (".", "..") or len(stem.encode()) > 240:
        stem = "x" + stem[:50]
    folder = tmp_path_factory.mktemp("n")
    code, said = run(folder, RUN.replace("SECONDS", "0.1"), name=f"{stem}.yaml")
    if is_name(stem):
        assert code == 0 and json.loads(said.splitlines()[-1])["outcome"] == "done"
    else:
        assert code == 2 and "E203" in said and "the file name" in said, said
        assert f"'{stem}.yaml'" in said or not stem.isprintable()  # control characters are shown escaped
