"""A state's key: what the engine between two ticks holds that can change what happens next, as
bytes that two equal situations share however their objects were made.

The pickle a state is copied with (`snapshot`) cannot be its key: its bytes depend on which equal
strings and tuples are one object (a name read from the program, or one copied with the state),
so two runs to the same situation would be explored twice. The key is written by value instead:
every object reachable from the engine through attributes, slots and containers, in order; an
object met again as its number (so sharing and cycles are kept); an object all states share (the
program, its machines and states, the stand-ins) as its number in that table; sets sorted.

Left out: caches and statistics (`SKIPPED`), which change nothing that can happen next. With
`relative`, every tick is written as its distance from the engine's tick.
"""

from __future__ import annotations

import hashlib
import pickle
from sys import intern
from typing import Any

# Attributes that are caches, statistics, the trace, the same in every state of a search, or a way
# back up the tree the key walks down (a frame's agent and caller, a region's owner, the engine).
SKIPPED: dict[str, frozenset[str]] = {
    "Frame": frozenset({"_scope", "_prefix", "text", "vars_shown", "vars_new", "agent", "up"}),
    "Region": frozenset({"owner"}),
    "Agent": frozenset({"stats", "entries", "clock", "rng", "robot", "inputs"}),
    "Team": frozenset({"engine", "by_name"}),
    "Engine": frozenset({"_time", "spans", "records", "trace", "breaks", "by_name", "dt"}),
    "RunClock": frozenset({"_time", "spans", "dt"}),
    "Ledger": frozenset({"records"}),
    "Arcs": frozenset({"records"}),
    "Messaging": frozenset({"by_name", "sent"}),
    "Message": frozenset({"id"}),  # numbers sends for the trace only
    "ChoosingWorld": frozenset({"decider", "n", "posted", "tick", "given", "delay", "flying"}),
    "AgentResult": frozenset({"time"}),
}
# Attributes that hold a tick (besides every `deadline`): written as a distance from the engine's.
TICKS: dict[str, frozenset[str]] = {
    "Engine": frozenset({"tick"}),
    "RunClock": frozenset({"tick"}),
    "Frame": frozenset({"state_deadline", "retry_at", "entered", "started"}),
    "Barrier": frozenset({"entered", "sent"}),
    "Message": frozenset({"sent_tick"}),
}
_ATOMS = frozenset({int, float, bool, type(None)})
_NOTHING: frozenset[str] = frozenset()
_UNSET = object()  # a slot never set
_NO_ATTRS: dict[str, Any] = {}


def _arrival(flying: tuple[int, int, Any]) -> tuple[int, int]:
    return flying[0], flying[1]


Layout = tuple[tuple[str, ...], frozenset[str], frozenset[str]]


class Keys:
    """Keys of engines: `shared` numbers the objects every state shares (by id); with `relative`,
    ticks are written as distances from the engine's tick (the tick itself left out)."""

    def __init__(
        self, shared: dict[int, int], relative: bool = True, unobserved: frozenset[str] = _NOTHING
    ) -> None:
        self.shared = shared
        self.unobserved = unobserved  # a frame's times that nothing reads (`build.unobserved`)
        self.relative = relative
        self.layouts: dict[type, Layout] = {}
        self.now = 0
        self.world: type = type(None)
        self.out: list[Any] = []
        self.seen: dict[int, int] = {}

    def __call__(self, engine: Any) -> bytes:
        # Flat: markers and values, every string interned, so that pickle's bytes of the list depend
        # on the values only (pickle writes a string met again as a reference to the first).
        self.now = engine.tick if self.relative else 0
        self.world = engine.world.__class__
        self.out = []
        self.seen = {}
        self._walk(engine)
        return hashlib.blake2b(pickle.dumps(self.out, protocol=5), digest_size=16).digest()

    def _walk(self, obj: Any) -> None:
        put = self.out.append
        cls = obj.__class__
        if cls in _ATOMS or cls is bytes:
            put(obj)
            return
        if cls is str:
            put(intern(obj))
            return
        ident = id(obj)
        number = self.shared.get(ident)
        if number is None:
            number = self.seen.get(ident)
            if number is None:
                self.seen[ident] = len(self.seen)
                self._new(obj, cls)
                return
            put("@")
        else:
            put("S")
        put(number)

    def _new(self, obj: Any, cls: type) -> None:
        put = self.out.append
        if cls is dict:
            put("{")
            put(len(obj))
            self._items(obj.items())
        elif cls is list or cls is tuple:
            put("[" if cls is list else "(")
            put(len(obj))
            self._values(obj)
        elif cls is set or cls is frozenset:
            put("s")
            put(len(obj))
            for v in sorted(obj, key=repr):
                self._walk(v)
        elif callable(obj) and not hasattr(obj, "__dict__") and not hasattr(obj, "__slots__"):
            put("f")
            put(intern(getattr(obj, "__qualname__", repr(obj))))
        else:
            self._object(obj, cls)

    def _values(self, values: Any) -> None:
        put, walk = self.out.append, self._walk
        for v in values:
            c = v.__class__
            if c in _ATOMS:
                put(v)
            elif c is str:
                put(intern(v))
            else:
                walk(v)

    def _items(self, items: Any) -> None:
        put, walk = self.out.append, self._walk
        for k, v in items:
            if k.__class__ is str:
                put(intern(k))
            else:
                walk(k)
            c = v.__class__
            if c in _ATOMS:
                put(v)
            elif c is str:
                put(intern(v))
            else:
                walk(v)

    def _object(self, obj: Any, cls: type) -> None:
        put = self.out.append
        slots, skipped, ticks = self.layouts.get(cls) or self._layout(cls)
        put("<")
        put(intern(cls.__name__))
        if cls is self.world:
            self._flying(obj)
        if slots:
            self._slots(obj, slots, ticks)
        attrs = getattr(obj, "__dict__", None)
        if attrs:
            self._attrs(attrs, skipped, ticks)
        put(">")

    def _slots(self, obj: Any, slots: tuple[str, ...], ticks: frozenset[str]) -> None:
        put, walk, now = self.out.append, self._walk, self.now
        for attr in slots:
            v: Any = getattr(obj, attr, _UNSET)
            c = v.__class__
            if c in _ATOMS:
                put(v - now if c is int and attr in ticks else v)
            elif c is str:
                put(intern(v))
            elif v is _UNSET:
                put("u")
            else:
                walk(v)

    def _attrs(self, attrs: dict[str, Any], skipped: frozenset[str], ticks: frozenset[str]) -> None:
        put, walk, now = self.out.append, self._walk, self.now
        for attr, v in attrs.items():
            if attr in skipped:
                continue
            put(intern(attr))
            c = v.__class__
            if c in _ATOMS:
                put(v - now if c is int and attr in ticks else v)
            elif c is str:
                put(intern(v))
            else:
                walk(v)

    def _flying(self, world: Any) -> None:
        # Messages in flight in the order they arrive in, each its arrival tick: the numbers that
        # break the world's ties are left out (SKIPPED), the order they give kept.
        self.out.append("flying")
        for arrives, _, message in sorted(world.flying, key=_arrival):
            self.out.append(arrives - self.now)
            self._walk(message)

    def _layout(self, cls: type) -> Layout:
        slots: list[str] = []
        for base in reversed(cls.__mro__):
            own = base.__dict__.get("__slots__", ())
            slots.extend([own] if isinstance(own, str) else own)
        skipped = SKIPPED.get(cls.__name__, _NOTHING)
        if cls.__name__ == "Frame":
            skipped = skipped | self.unobserved
        ticks = TICKS.get(cls.__name__, _NOTHING) | {"deadline"} if self.relative else _NOTHING
        kept = tuple(s for s in slots if s not in skipped and s != "__dict__")
        found = self.layouts[cls] = (kept, skipped, ticks)
        return found
