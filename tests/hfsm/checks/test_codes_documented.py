"""Every code the checks can give is listed in docs/CHECKS.md, with an example, and no other."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
CODE = re.compile(r'"([EW][1-4]\d\d)"')


def test_every_code_in_the_source_is_documented_once_with_an_example() -> None:
    used = {code for path in (ROOT / "hfsm").rglob("*.py") for code in CODE.findall(path.read_text())}
    rows = re.findall(
        r"^\| ([EW]\d{3}) \| ([^|]+) \| ([^|]+) \| ([^|]+) \|$",
        (ROOT / "docs" / "CHECKS.md").read_text(),
        re.M,
    )
    documented = [code for code, *_ in rows]
    assert len(documented) == len(set(documented))
    assert set(documented) == used, sorted(used ^ set(documented))
    assert all(example.strip() for _, _, example, _ in rows)
