"""Primitives declared as data: what a caller needs to know, and where the function lives.

A primitive package whose functions import something heavy (a simulator, OpenCV) ships its
declarations as a JSON file generated from its `@primitive` functions; its `hfsm.primitives` entry
point reads that file, and the functions are imported only when a run calls them. Regenerate with

    python -m hfsm.declarations PACKAGE.MODULE:ATTR > FILE.json

where ATTR is a sequence of primitives (or a function returning one).
"""

from __future__ import annotations

import importlib
import json
import sys
from collections.abc import Iterable, Sequence
from typing import Any

from hfsm.cli.quiet import stdout_to_stderr
from hfsm.primitive import Primitive
from hfsm.spec import BehaviourSpec, ParamSpec

FORMAT = 1


def to_data(primitives: Iterable[Primitive]) -> dict[str, Any]:
    """The declarations of some primitives, as JSON-ready data (in the order given)."""
    return {"format": FORMAT, "primitives": [_one(p) for p in primitives]}


def _one(prim: Primitive) -> dict[str, Any]:
    spec = prim.spec
    return {
        "name": spec.name,
        "target": prim.where,
        "world": spec.world,
        "doc": spec.doc,
        "params": {
            p.name: {"type": p.type, **({} if p.required else {"default": p.default})}
            for p in spec.params.values()
        },
        "outcomes": list(spec.outcomes),
        "failures": sorted(spec.failures),
        "outputs": None if spec.outputs is None else sorted(spec.outputs),
    }


def from_data(data: dict[str, Any]) -> list[Primitive]:
    """Primitives from declarations; each function is imported at its first call."""
    if data.get("format") != FORMAT:
        raise ValueError(f"declarations of format {data.get('format')!r}; this hfsm reads format {FORMAT}")
    return [_primitive(d) for d in data["primitives"]]


def _primitive(d: dict[str, Any]) -> Primitive:
    params = {
        name: ParamSpec(name, p["type"], "default" not in p, p.get("default"))
        for name, p in d["params"].items()
    }
    outputs = d["outputs"]
    spec = BehaviourSpec(
        name=d["name"],
        kind="primitive",
        params=params,
        outcomes=tuple(d["outcomes"]),
        failures=frozenset(d["failures"]),
        outputs=None if outputs is None else frozenset(outputs),
        doc=d["doc"],
        world=d["world"],
    )
    return Primitive(spec, d["target"])


def dumps(primitives: Iterable[Primitive]) -> str:
    return json.dumps(to_data(primitives), indent=1, ensure_ascii=False) + "\n"


def loads(text: str) -> list[Primitive]:
    return from_data(json.loads(text))


def _load_attr(where: str) -> Sequence[Primitive]:
    module, _, attr = where.partition(":")
    found = getattr(importlib.import_module(module), attr)
    return found() if callable(found) else found  # type: ignore[no-any-return]


def main(argv: Sequence[str] | None = None) -> int:
    args = list(sys.argv[1:] if argv is None else argv)
    if len(args) != 1 or ":" not in args[0]:
        print("usage: python -m hfsm.declarations PACKAGE.MODULE:ATTR > FILE.json", file=sys.stderr)
        return 2
    with stdout_to_stderr():  # a simulator's banner must not land in the JSON
        primitives = _load_attr(args[0])
    sys.stdout.write(dumps(primitives))
    return 0


if __name__ == "__main__":
    sys.exit(main())
