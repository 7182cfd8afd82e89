"""An agent's mailbox: its messages in arrival order, and how many of each name it holds.

Messages nobody takes stay for the rest of the run (docs/REFERENCE.md#messages-between-agents), so a
long run of a large team holds thousands. Most looks into a mailbox find nothing: the counts answer
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
        self._names: list[str] = [message.name for message in self]
        for name in self._names:
            self._count(name, 1)

    def __reduce__(self) -> tuple[type[Mailbox], tuple[list[Message]]]:
        """Copied and pickled (hfsm-verify's states) as its messages, counted again when rebuilt."""
        return (Mailbox, (list(self),))

    def _count(self, name: str, change: int) -> None:
        left = self.counts.get(name, 0) + change
        if left:
            self.counts[name] = left
        else:
            del self.counts[name]

    def append(self, message: Message) -> None:
        super().append(message)
        self._names.append(message.name)
        self._count(message.name, 1)

    def insert(self, index: SupportsIndex, message: Message) -> None:
        super().insert(index, message)
        self._names.insert(index, message.name)
        self._count(message.name, 1)

    def pop(self, index: SupportsIndex = -1) -> Message:
        message = super().pop(index)
        self._names.pop(index)
        self._count(message.name, -1)
        return message

    def __delitem__(self, index: SupportsIndex | slice) -> None:
        if isinstance(index, slice):
            raise TypeError("a mailbox deletes one message at a time")
        self._count(self[index].name, -1)
        super().__delitem__(index)
        del self._names[index]

    def clear(self) -> None:
        super().clear()
        self._names.clear()
        self.counts.clear()

    def take(self, names: Collection[str], prefix: str = "") -> Message | None:
        """Remove and return the earliest message whose name is in `names`, sent under the scope
        whose names begin with `prefix`: `scope/name`, or a bare name outside every scope."""
        counts = self.counts
        held = [prefix + name for name in names if prefix + name in counts]
        if not held:
            return None
        index = self._names.index
        return self.pop(index(held[0]) if len(held) == 1 else min(index(name) for name in held))
