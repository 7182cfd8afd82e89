"""States of a run as bytes: a pickle of the engine in which what all states share is written as a
reference, never as itself. The bytes copy a state and hash it.

What all states share: the objects reachable from the compiled program, the stand-ins, the decider
and the random generator (which stand-ins never draw from); and what the first state dumped holds
that never changes, its classes (with those of the engine's modules) and their attribute names.
Most of it is a table (`seed`) put in the pickler's memo and in the unpickler's before each copy:
the C pickler writes each as a memo reference with no call back into Python, and a load makes none
of them again but gives the table's very objects. Shared objects of classes a state seldom holds
(the program's specs) stay out of the table, which is copied for each copy, and are written by a
reducer instead.

Two quirks of CPython's pickle decide the format. An unpickler's memo set from a dict is dropped
(3.11), so the table is put in one by loading a pickle that stores each object through
`persistent_load`, and copied from it; and a copied unpickler memo does not know its length, so a
state is written with protocol 3, whose memo writes name their index, in one protocol 4 frame (one
read of the whole state instead of one per opcode).
"""

from __future__ import annotations

import copyreg
import hashlib
import io
import itertools
import pickle
import struct
import sys
from collections.abc import Callable, Iterable
from typing import Any

_ATOMS = (str, int, float, bool, bytes, type(None))
_CONTAINERS = (dict, list, tuple, set, frozenset)
_PROTOCOL = 3  # memo writes name their index (BINPUT), see the module's docstring
_FRAME = b"\x80\x04\x95"  # PROTO 4, FRAME: what follows is one frame of the length written next
_TABLES: dict[int, list[Any]] = {}  # a Snapshots' shared objects left out of its table, by its number
_NUMBERS = itertools.count()
STATE_MODULES = ("hfsm.runtime", "hfsm.builtins", "hfsm.verify", "hfsm.primitive", "hfsm.world")
_RUNTIME = "hfsm.runtime"


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


def sharable(shared: dict[int, Any]) -> list[Any]:
    """Of the `shared` objects, those a state's copy writes as references: not containers nor
    functions (those a state holds are its own)."""
    return [o for o in shared.values() if not isinstance(o, _CONTAINERS) and not callable(o)]


def shared_numbers(shared: dict[int, Any]) -> dict[int, int]:
    """The objects a state's key writes as a number (`canon`): those `Snapshots` shares."""
    return {id(o): i for i, o in enumerate(sharable(shared))}


def state_parts(state: Any, shared: dict[int, Any]) -> tuple[list[type], list[str], list[Any]]:
    """The classes of a state's own objects and their attribute names, and the objects of `shared`
    it holds, in the order met. (Strings held as values are not among them: an equal string made
    later would be written by value where the one met here is a reference, and two equal states
    would have different bytes.)"""
    classes: dict[type, None] = {}
    strings: dict[int, str] = {}
    held: dict[int, Any] = {}
    seen: set[int] = set()
    stack = [state]
    while stack:
        obj = stack.pop()
        if id(obj) in shared:
            held.setdefault(id(obj), obj)
            continue
        if isinstance(obj, _ATOMS) or id(obj) in seen or isinstance(obj, type):
            continue
        seen.add(id(obj))
        if isinstance(obj, dict):
            stack.extend(reversed([*obj.keys(), *obj.values()]))
            continue
        if isinstance(obj, list | tuple | set | frozenset):
            ordered = sorted(obj, key=repr) if isinstance(obj, set | frozenset) else list(obj)
            stack.extend(reversed(ordered))
            if obj.__class__ not in _CONTAINERS:
                classes.setdefault(obj.__class__)
            continue
        cls = obj.__class__
        classes.setdefault(cls)
        names = [n for n in copyreg._slotnames(cls) if hasattr(obj, n)]  # type: ignore[attr-defined]
        attrs = getattr(obj, "__dict__", {})
        for name in [*names, *attrs]:
            strings.setdefault(id(name), name)
        stack.extend(reversed([*(getattr(obj, n) for n in names), *attrs.values()]))
    return list(classes), list(strings.values()), list(held.values())


def own_classes() -> list[type]:
    """The classes of the modules whose objects a state may hold (`STATE_MODULES`), by module, name."""
    found: dict[type, None] = {}
    for name, module in sorted(sys.modules.items()):
        if name.startswith(STATE_MODULES) and module is not None:
            for value in vars(module).values():
                if isinstance(value, type) and value.__module__ == name and "<" not in value.__qualname__:
                    found.setdefault(value)
    return list(found)


def _shared(table: int, key: int) -> Any:
    """What a state's pickle holds in the place of a shared object left out of the table (module
    level: pickle finds it)."""
    return _TABLES[table][key]


class Snapshots:
    """Dumps and loads engines, sharing the objects given (but containers and functions: those a
    state holds are copied, and a state holds no function) and what the first state dumped holds
    that never changes (its classes, its attribute names).

    Shared objects of the engine's own classes and those the first state holds are in the table;
    the others (the program's specs, which a state seldom holds) are written by a reducer, a call
    back into Python each, so that copying the table for each copy stays cheap."""

    def __init__(self, shared: dict[int, Any]) -> None:
        self.shared = shared
        self.objects = sharable(shared)
        self.number = next(_NUMBERS)
        self.seed: list[Any] = []
        self.table: dict[Any, Any] = {}
        self._pickler_memo: Any = None
        self._unpickler_memo: Any = None

    def _seed(self, engine: Any) -> None:
        made_by, (state,) = engine.__reduce__()  # an engine: the function that makes it again, its state
        classes, strings, held = state_parts(state, self.shared)
        later = own_classes()  # those of objects that later states make (events, results, built-ins)
        names = [n for cls in later for n in copyreg._slotnames(cls)]  # type: ignore[attr-defined]
        kinds = {type(o) for o in held}
        objects = [o for o in self.objects if type(o) in kinds or type(o).__module__.startswith(_RUNTIME)]
        seed = {id(o): o for o in [*objects, made_by, *classes, *later, *strings, *names]}
        self.seed = list(seed.values())
        rest = [o for o in self.objects if id(o) not in seed]
        _TABLES[self.number] = rest
        keys = {id(obj): i for i, obj in enumerate(rest)}
        self.table = copyreg.dispatch_table.copy()
        for cls in {type(o) for o in rest}:
            self.table[cls] = self._reducer(keys)
        pickler = pickle.Pickler(io.BytesIO(), protocol=_PROTOCOL)
        pickler.memo = {id(o): (i, o) for i, o in enumerate(self.seed)}
        self._pickler_memo = pickler.memo
        # BININT i, BINPERSID, LONG_BINPUT i, POP for each; then None.
        put = b"".join(b"J%sQr%s0" % (struct.pack("<i", i), struct.pack("<I", i)) for i in range(len(seed)))
        unpickler = pickle.Unpickler(io.BytesIO(b"\x80\x03" + put + b"N."))
        unpickler.persistent_load = self.seed.__getitem__  # type: ignore[method-assign]
        unpickler.load()
        self._unpickler_memo = unpickler.memo

    def _reducer(self, keys: dict[int, int]) -> Callable[[Any], Any]:
        number = self.number

        def reduce(obj: Any) -> Any:
            key = keys.get(id(obj))
            if key is None:
                return obj.__reduce_ex__(_PROTOCOL)
            return _shared, (number, key)

        return reduce

    def dump(self, engine: Any) -> bytes:
        if self._pickler_memo is None:
            self._seed(engine)
        out = io.BytesIO()
        out.write(_FRAME + bytes(8))
        pickler = pickle.Pickler(out, protocol=_PROTOCOL)
        pickler.memo = self._pickler_memo
        pickler.dispatch_table = self.table
        pickler.dump(engine)
        data = out.getbuffer()
        data[3:11] = (len(data) - 11).to_bytes(8, "little")  # one frame: the protocol 3 pickle
        del data
        return out.getvalue()

    def load(self, data: bytes) -> Any:
        unpickler = pickle.Unpickler(io.BytesIO(data))
        unpickler.memo = self._unpickler_memo
        return unpickler.load()

    def close(self) -> None:
        self._pickler_memo = self._unpickler_memo = None
        _TABLES.pop(self.number, None)


def digest(data: bytes) -> bytes:
    return hashlib.blake2b(data, digest_size=16).digest()
