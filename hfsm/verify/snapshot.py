"""States of a run as bytes: a pickle of the engine, with what all states share (the compiled
program, stand-ins, the decider) pickled by reference. The bytes copy a state and hash it."""

from __future__ import annotations

import hashlib
import io
import pickle
from collections.abc import Iterable
from typing import Any

_ATOMS = (str, int, float, bool, bytes, type(None))


def shared_objects(roots: Iterable[Any]) -> dict[int, Any]:
    """Every object reachable from `roots` (through attributes, slots and containers), by id."""
    found: dict[int, Any] = {}
    stack = list(roots)
    while stack:
        obj = stack.pop()
        if isinstance(obj, _ATOMS) or id(obj) in found or isinstance(obj, type):
            continue
        found[id(obj)] = obj
        if isinstance(obj, dict):
            stack.extend(obj.keys())
            stack.extend(obj.values())
        elif isinstance(obj, list | tuple | set | frozenset):
            stack.extend(obj)
        elif callable(obj) and not hasattr(obj, "__slots__") and not hasattr(obj, "__dict__"):
            continue
        else:
            for name in getattr(type(obj), "__slots__", ()):
                if hasattr(obj, name):
                    stack.append(getattr(obj, name))
            stack.extend(getattr(obj, "__dict__", {}).values())
    return found


class Snapshots:
    """Dumps and loads engines, sharing the objects given."""

    def __init__(self, shared: dict[int, Any]) -> None:
        self.shared = shared
        self.by_key = list(shared.values())
        self.keys = {id(obj): i for i, obj in enumerate(self.by_key)}

    def dump(self, engine: Any) -> bytes:
        out = io.BytesIO()
        pickler = pickle.Pickler(out, protocol=pickle.HIGHEST_PROTOCOL)
        keys = self.keys
        pickler.persistent_id = lambda obj: keys.get(id(obj))  # type: ignore[method-assign]
        pickler.dump(engine)
        return out.getvalue()

    def load(self, data: bytes) -> Any:
        unpickler = pickle.Unpickler(io.BytesIO(data))
        by_key = self.by_key
        unpickler.persistent_load = by_key.__getitem__  # type: ignore[method-assign]
        return unpickler.load()


def digest(data: bytes) -> bytes:
    return hashlib.blake2b(data, digest_size=16).digest()
