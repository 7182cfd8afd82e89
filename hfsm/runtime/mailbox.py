"""An agent's mailbox: its messages in arrival order, and how many of each name it holds.

Messages nobody takes stay for the rest of the run (docs/REFERENCE.md#messages-between-agents), so a
long run of a large team holds thousands, unless sent with `keep: last` (a status: the sender's newest
copy replaces the one not yet taken). Most looks into a mailbox find nothing: the counts answer
those at once. A look that will find a message searches a list of the messages' names kept beside
them (`list.index`, in C) rather than walking the messages in Python: a room's heartbeats are taken
from behind thousands of messages nobody takes.
"""

from __future__ import annotations

from collections.abc import Collection, Iterable
from typing import SupportsIndex

from hfsm.primitive import Message


class Mailbox(list[Message]):
    """A list of messages (the engine appends, takes, holds and puts back) that keeps `counts` and
    the messages' names in order."""

    def __init__(self, messages: Iterable[Message] = ()) -> None:
        super().__init__(messages)
        self.counts: dict[str, int] = {}
        self.pairs: dict[tuple[str, str], int] = {}  # how many of each (name, sender): for `replace`
        self._names: list[str] = [message.name for message in self]
        for message in self:
            self._count(message, 1)

    def __reduce__(self) -> tuple[type[Mailbox], tuple[list[Message]]]:
        """Copied and pickled (hfsm-verify's states) as its messages, counted again when rebuilt."""
        return (Mailbox, (list(self),))

    def _count(self, message: Message, change: int) -> None:
        name, counts, pairs = message.name, self.counts, self.pairs
        left = counts.get(name, 0) + change
        if left:
            counts[name] = left
        else:
            del counts[name]
        key = (name, message.sender)
        left = pairs.get(key, 0) + change
        if left:
            pairs[key] = left
        else:
            del pairs[key]

    def append(self, message: Message) -> None:
        super().append(message)
        self._names.append(message.name)
        self._count(message, 1)

    def insert(self, index: SupportsIndex, message: Message) -> None:
        super().insert(index, message)
        self._names.insert(index, message.name)
        self._count(message, 1)

    def pop(self, index: SupportsIndex = -1) -> Message:
        message = super().pop(index)
        self._names.pop(index)
        self._count(message, -1)
        return message

    def __delitem__(self, index: SupportsIndex | slice) -> None:
        if isinstance(index, slice):
            raise TypeError("a mailbox deletes one message at a time")
        self._count(self[index], -1)
        super().__delitem__(index)
        del self._names[index]

    def clear(self) -> None:
        super().clear()
        self._names.clear()
        self.counts.clear()
        self.pairs.clear()

    def replace(self, message: Message) -> bool:
        """Append `message` in place of every message of its name from its sender not yet taken
        (`send`'s `keep: last`): whether there was one. Appended either way."""
        name, sender = message.name, message.sender
        many = found = self.pairs.get((name, sender), 0)
        if many:
            i = 0
            while many:
                old = self[i]
                if old.sender == sender and old.name == name:
                    del self[i]
                    many -= 1
                else:
                    i += 1
        self.append(message)
        return found > 0

    def take(self, names: Collection[str], prefix: str = "") -> Message | None:
        """Remove and return the earliest message whose name is in `names`, sent under the scope
        whose names begin with `prefix`: `scope/name`, or a bare name outside every scope."""
        counts = self.counts
        held = [prefix + name for name in names if prefix + name in counts]
        if not held:
            return None
        index = self._names.index
        return self.pop(index(held[0]) if len(held) == 1 else min(index(name) for name in held))
