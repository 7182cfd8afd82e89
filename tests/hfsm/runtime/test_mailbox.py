"""The mailbox keeps its counts of names whatever the engine does to it (append, take, hold, put back,
clear), and takes the message a plain walk of the list takes."""

from __future__ import annotations

import copy
import pickle

from hypothesis import given
from hypothesis import strategies as st

from hfsm.primitive import Message
from hfsm.runtime.mailbox import Mailbox

NAMES = st.sampled_from(["a", "b", "s/a", "s/b", "t/a", "s/"])


def _walk(messages: list[Message], names: tuple[str, ...], prefix: str) -> int | None:
    """The index the engine's list walk took before the counts (agent.take_message)."""
    for i, message in enumerate(messages):
        name = message.name
        if name.startswith(prefix) and name[len(prefix):] in names:
            return i
    return None


OPS = st.lists(
    st.one_of(
        st.tuples(st.just("append"), NAMES, st.integers(0, 9)),
        st.tuples(st.just("replace"), NAMES, st.sampled_from(["x", "z"])),
        st.tuples(st.just("take"), st.lists(st.sampled_from(["a", "b", ""]), max_size=3), st.sampled_from(["", "s/", "t/"])),
        st.tuples(st.just("insert"), NAMES, st.integers(0, 12)),
        st.tuples(st.just("delete"), st.integers(0, 12)),
        st.tuples(st.just("clear")),
    ),
    max_size=40,
)


@given(OPS)
def test_counts_follow_the_list_and_take_is_the_walk(ops: list[tuple[object, ...]]) -> None:
    box, plain = Mailbox(), list[Message]()
    for op in ops:
        kind = op[0]
        if kind == "append":
            message = Message(str(op[1]), "x", "y", {"n": op[2]}, 0)
            box.append(message)
            plain.append(message)
        elif kind == "replace":  # keep: last
            message = Message(str(op[1]), str(op[2]), "y", {}, 0, "last")
            replaced = box.replace(message)
            kept = [m for m in plain if m.name != message.name or m.sender != message.sender]
            assert replaced == (len(kept) < len(plain))
            plain = [*kept, message]
        elif kind == "insert":
            message = Message(str(op[1]), "x", "y", {}, 0)
            box.insert(int(op[2]), message)  # type: ignore[call-overload]
            plain.insert(int(op[2]), message)  # type: ignore[call-overload]
        elif kind == "delete" and plain:
            at = int(op[1]) % len(plain)  # type: ignore[call-overload]
            del box[at]
            del plain[at]
        elif kind == "clear":
            box.clear()
            plain.clear()
        elif kind == "take":
            names, prefix = tuple(op[1]), str(op[2])  # type: ignore[arg-type]
            at = _walk(plain, names, prefix)
            got = box.take(names, prefix)
            assert got is (None if at is None else plain.pop(at))
        assert list(box) == plain
        counts: dict[str, int] = {}
        for message in plain:
            counts[message.name] = counts.get(message.name, 0) + 1
        assert box.counts == counts
        pairs: dict[tuple[str, str], int] = {}
        for message in plain:
            pairs[message.name, message.sender] = pairs.get((message.name, message.sender), 0) + 1
        assert box.pairs == pairs


def test_a_mailbox_made_from_messages_counts_them() -> None:
    box = Mailbox([Message("a", "x", "y", {}, 0), Message("a", "x", "y", {}, 1), Message("b", "x", "y", {}, 1)])
    assert box.counts == {"a": 2, "b": 1}
    assert box.pop().name == "b" and box.counts == {"a": 2}


def test_a_mailbox_pickled_or_copied_keeps_its_counts() -> None:
    box = Mailbox([Message("a", "x", "y", {"n": 1}, 0), Message("b", "x", "y", {}, 1)])
    for copied in (pickle.loads(pickle.dumps(box, protocol=5)), copy.deepcopy(box), copy.copy(box)):
        assert isinstance(copied, Mailbox) and list(copied) == list(box) and copied.counts == {"a": 1, "b": 1}
        assert copied.take(("a",)) == box[0] and copied.counts == {"b": 1} and box.counts == {"a": 1, "b": 1}
