"""States of a run as bytes: a pickle of the engine, with what all states share (the compiled
program, stand-ins, the decider, each agent's random generator, which stand-ins never draw from)
pickled as a reference. The bytes copy a state and hash it.

Shared objects are found by type (`copyreg`-style reducers in the pickler's dispatch table), so
that the C pickler calls back into Python only for them, not for every object of a state.
"""

from __future__ import annotations

import copyreg
import hashlib
import io
import itertools
import pickle
from collections.abc import Callable, Iterable
from typing import Any

_ATOMS = (str, int, float, bool, bytes, type(None))
_CONTAINERS = (dict, list, tuple, set, frozenset)
_TABLES: dict[int, list[Any]] = {}  # a Snapshots' shared objects, by its number
_NUMBERS = itertools.count()


def _shared(table: int, key: int) -> Any:
    """What a state's pickle holds in the place of a shared object (module level: pickle finds it)."""
    return _TABLES[table][key]


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


def shared_numbers(shared: dict[int, Any]) -> dict[int, int]:
    """The objects a state's key writes as a number (`canon`): those `Snapshots` shares."""
    objects = [o for o in shared.values() if not isinstance(o, _CONTAINERS) and not callable(o)]
    return {id(o): i for i, o in enumerate(objects)}


class Snapshots:
    """Dumps and loads engines, sharing the objects given (but containers and functions: those a
    state holds are copied, and a state holds no function)."""

    def __init__(self, shared: dict[int, Any]) -> None:
        objects = [o for o in shared.values() if not isinstance(o, _CONTAINERS) and not callable(o)]
        self.number = next(_NUMBERS)
        _TABLES[self.number] = objects
        keys = {id(obj): i for i, obj in enumerate(objects)}
        self.table = copyreg.dispatch_table.copy()
        for cls in {type(o) for o in objects}:
            self.table[cls] = self._reducer(keys)

    def _reducer(self, keys: dict[int, int]) -> Callable[[Any], Any]:
        number = self.number

        def reduce(obj: Any) -> Any:
            key = keys.get(id(obj))
            if key is None:
                return obj.__reduce_ex__(pickle.HIGHEST_PROTOCOL)
            return _shared, (number, key)

        return reduce

    def dump(self, engine: Any) -> bytes:
        out = io.BytesIO()
        pickler = pickle.Pickler(out, protocol=pickle.HIGHEST_PROTOCOL)
        pickler.dispatch_table = self.table
        pickler.dump(engine)
        return out.getvalue()

    def load(self, data: bytes) -> Any:
        return pickle.loads(data)

    def close(self) -> None:
        _TABLES.pop(self.number, None)


def digest(data: bytes) -> bytes:
    return hashlib.blake2b(data, digest_size=16).digest()
