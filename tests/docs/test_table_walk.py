"""The walk round the table of docs/REFERENCE.md (trigonometry in YAML alone) gives the corners that
plane geometry gives, in world `none`, for any table, heading and margin."""

from __future__ import annotations

import io
import json
import math
import re
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hfsm.cli.run import main

PAGE = Path(__file__).resolve().parents[2] / "docs" / "REFERENCE.md"


def machine(folder: Path) -> Path:
    block = re.search(r"```yaml\n(# example: table_walk\.yaml.*?)```", PAGE.read_text(), re.S)
    assert block is not None
    path = folder / "table_walk.yaml"
    path.write_text(block.group(1))
    return path


def expected(centre: list[float], size: list[float], heading: float, margin: float) -> list[list[float]]:
    """The corners, a margin out, turned about the centre: counter-clockwise from front-left."""
    a, b = size[0] / 2 + margin, size[1] / 2 + margin
    c, s = math.cos(math.radians(heading)), math.sin(math.radians(heading))
    local = [(a, b), (-a, b), (-a, -b), (a, -b)]
    return [[centre[0] + u * c - v * s, centre[1] + u * s + v * c] for u, v in local]


def run(path: Path, *params: str) -> dict[str, object]:
    out, err = io.StringIO(), io.StringIO()
    argv = [str(path), "--world", "none", "--json", "--quiet"]
    for param in params:
        argv += ["--param", param]
    with redirect_stdout(out), redirect_stderr(err):
        code = main(argv)
    assert code == 0, err.getvalue()
    assert "warning" not in err.getvalue()
    result: dict[str, object] = json.loads(out.getvalue())
    return result


def test_the_page_s_numbers(tmp_path: Path) -> None:
    got = run(machine(tmp_path))
    points = got["outputs"]["points"]  # type: ignore[index]
    for point, want in zip(points, expected([2, 1], [1.6, 0.8], 30, 0.5), strict=True):
        assert point == [round(want[0], 3), round(want[1], 3)]
    assert got["time"] == 4


@settings(max_examples=10, deadline=None)
@given(
    heading=st.floats(-360, 360),
    length=st.floats(0.2, 3),
    width=st.floats(0.2, 3),
    margin=st.floats(0, 1),
    x=st.floats(-10, 10),
)
def test_any_table(
    tmp_path_factory: pytest.TempPathFactory, heading: float, length: float, width: float, margin: float, x: float
) -> None:
    folder = tmp_path_factory.mktemp("walk")
    sizes = f"size=[{length!r}, {width!r}]"
    got = run(machine(folder), f"heading={heading!r}", sizes, f"margin={margin!r}", f"centre=[{x!r}, 0]")["outputs"]
    want = expected([x, 0], [length, width], heading, margin)
    for point, corner in zip(got["points"], want, strict=True):  # type: ignore[index]
        assert math.dist(point, corner) < 1e-3
    assert abs(got["side"] - 2 * (length / 2 + margin)) < 3e-3  # type: ignore[index]
