"""The properties a user states in a file (`--props FILE`), read and checked before any search.

```yaml
never_together: [lift]                # never two agents in state `lift` at once
left_within: {meet: 10}               # state `meet` is always left within 10 s
at_end: "sum(1 for a in outputs if outputs[a]['role'] == 'leader') == 1"
```

A state is named by its path's end (`meet`, or `announce/listen`). `at_end` is a Python expression
over `outputs` (agent -> outputs), `outcomes` (agent -> outcome), `failed` (agents that failed) and
`agents`, evaluated once every agent has ended; only plain expressions, comprehensions and the calls
below are allowed.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from hfsm.errors import Finding, UserError
from hfsm.names import did_you_mean
from hfsm.yamlio import Document, read_mapping

CALLS = {"len": len, "sum": sum, "min": min, "max": max, "abs": abs, "all": all, "any": any, "sorted": sorted}
_NODES = (
    ast.Expression, ast.BoolOp, ast.BinOp, ast.UnaryOp, ast.Compare, ast.IfExp, ast.Call, ast.Constant,
    ast.Name, ast.Load, ast.Store, ast.Subscript, ast.List, ast.Tuple, ast.Dict, ast.Set, ast.GeneratorExp,
    ast.ListComp, ast.SetComp, ast.comprehension, ast.And, ast.Or, ast.Not, ast.Eq, ast.NotEq, ast.Lt,
    ast.LtE, ast.Gt, ast.GtE, ast.In, ast.NotIn, ast.Is, ast.IsNot, ast.Add, ast.Sub, ast.Mult, ast.Div,
    ast.Mod, ast.FloorDiv, ast.USub, ast.UAdd, ast.Slice,
)  # fmt: skip
NAMES = {"outputs", "outcomes", "failed", "agents"}


@dataclass
class Props:
    never_together: list[tuple[str, ...]] = field(default_factory=list)
    left_within: list[tuple[tuple[str, ...], float]] = field(default_factory=list)
    at_end: str = ""
    at_end_code: Any = None

    def holds_at_end(self, names: dict[str, Any]) -> bool | str:
        """Whether `at_end` holds, or the error its evaluation raised, as text."""
        try:
            return bool(eval(self.at_end_code, {"__builtins__": CALLS, **names}))
        except Exception as exc:  # a user's expression: any error is a violation to report
            return f"{type(exc).__name__}: {exc}"


def read_props(path: Path, states: set[str]) -> Props:
    """The file's properties; every problem at once as FILE:LINE:COL (UserError)."""
    doc = read_mapping(path, "properties")
    props, problems = Props(), list[Finding]()
    for key, value in doc.data.items():
        if key == "never_together":
            props.never_together = _states(doc, key, value, states, problems)
        elif key == "left_within":
            if not isinstance(value, dict):
                problems.append(doc.finding((key,), "E370", "left_within: a mapping of state to seconds"))
                continue
            for name, seconds in value.items():
                found = _state(doc, (key, name), name, states, problems, key=True)
                if not isinstance(seconds, int | float) or isinstance(seconds, bool) or seconds <= 0:
                    problems.append(doc.finding((key, name), "E370", f"{seconds!r}: a number of seconds > 0"))
                elif found is not None:
                    props.left_within.append((found, float(seconds)))
        elif key == "at_end":
            _at_end(doc, value, props, problems)
        else:
            hint = did_you_mean(str(key), ["never_together", "left_within", "at_end"]) or ""
            problems.append(doc.finding((key,), "E370", f"unknown property '{key}'{hint}", key=True))
    if problems:
        raise UserError(problems)
    return props


def _states(
    doc: Document, key: str, value: Any, states: set[str], problems: list[Finding]
) -> list[tuple[str, ...]]:
    if not isinstance(value, list):
        problems.append(doc.finding((key,), "E370", f"{key}: a list of states"))
        return []
    found = [_state(doc, (key, i), name, states, problems) for i, name in enumerate(value)]
    return [f for f in found if f is not None]


def _state(
    doc: Document,
    where: tuple[Any, ...],
    name: Any,
    states: set[str],
    problems: list[Finding],
    *,
    key: bool = False,
) -> tuple[str, ...] | None:
    if not isinstance(name, str) or not name:
        problems.append(doc.finding(where, "E370", f"{name!r}: a state's name or path (a/b)", key=key))
        return None
    parts = tuple(name.split("/"))
    unknown = [p for p in parts if p not in states]
    if unknown:
        hint = did_you_mean(unknown[0], sorted(states)) or ""
        problems.append(doc.finding(where, "E371", f"no state '{unknown[0]}' in the machines{hint}", key=key))
        return None
    return parts


def _at_end(doc: Document, value: Any, props: Props, problems: list[Finding]) -> None:
    if not isinstance(value, str):
        problems.append(doc.finding(("at_end",), "E372", "at_end: an expression, as text"))
        return
    try:
        tree = ast.parse(value, mode="eval")
    except SyntaxError as exc:
        problems.append(doc.finding(("at_end",), "E372", f"at_end: {exc.msg}"))
        return
    bound = {
        t.id
        for node in ast.walk(tree)
        if isinstance(node, ast.comprehension)
        for t in ast.walk(node.target)
        if isinstance(t, ast.Name)
    }
    for node in ast.walk(tree):
        if not isinstance(node, _NODES):
            problems.append(doc.finding(("at_end",), "E372", f"at_end: {type(node).__name__} is not allowed"))
            return
        if isinstance(node, ast.Call) and not (isinstance(node.func, ast.Name) and node.func.id in CALLS):
            problems.append(
                doc.finding(("at_end",), "E372", f"at_end: only {', '.join(sorted(CALLS))} may be called")
            )
            return
        if isinstance(node, ast.Name) and node.id not in NAMES | bound | set(CALLS):
            hint = did_you_mean(node.id, sorted(NAMES)) or ""
            problems.append(doc.finding(("at_end",), "E372", f"at_end: unknown name '{node.id}'{hint}"))
            return
    props.at_end = value
    props.at_end_code = compile(tree, str(doc.file), "eval")
