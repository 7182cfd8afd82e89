"""The history as a JSON file (`--history FILE`): written sorted, read with every error at its place.

    {"version": 1,
     "pairs":  [{"robots": ["r0", "r1"], "n_s": 2, "n_f": 1}],
     "robots": [{"id": "r0", "n_s": 1, "n_f": 0, "belief": 0.52}]}

`belief` is optional. The reader parses with PyYAML's composer (JSON is YAML's flow style), which
keeps the line and column of every value, and converts scalars itself (PyYAML 1.1 would read
`1e-05` as a string).
"""

from __future__ import annotations

import difflib
import json
import math
import os
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import TypeVar

import yaml

from hfsm_behaviours.tararc.grouping import Pair
from hfsm_behaviours.tararc.history import History, Record

VERSION = 1
T = TypeVar("T")


Problem = tuple[str, int, int, str]
"""(file, line, column, message), 1-based."""


class HistoryError(ValueError):
    """A bad history file: `problems` are every one of them, `errors` the same as `FILE:LINE:COL: message`."""

    def __init__(self, problems: list[Problem]) -> None:
        self.problems = problems
        self.errors = [f"{file}:{line}:{col}: {message}" for file, line, col, message in problems]
        super().__init__("\n".join(self.errors))


def dumps(history: History) -> str:
    doc = {
        "version": VERSION,
        "pairs": [{"robots": list(k), "n_s": r.n_s, "n_f": r.n_f} for k, r in sorted(history.pairs.items())],
        "robots": [_robot_entry(i, history) for i in sorted(set(history.robots) | set(history.beliefs))],
    }
    return json.dumps(doc, indent=2) + "\n"


def _robot_entry(robot: str, history: History) -> dict[str, object]:
    rec = history.robot_record(robot)
    entry: dict[str, object] = {"id": robot, "n_s": rec.n_s, "n_f": rec.n_f}
    if robot in history.beliefs:
        entry["belief"] = history.beliefs[robot]
    return entry


def save(path: Path, history: History) -> None:
    """Write atomically: a reader (or a run stopped mid-write, or a crash) sees the old file or the
    new one, never part of one. The new file is written in full to a temporary file in the same
    folder, flushed to the disk, then renamed over the old (os.replace is atomic on one file system);
    it keeps the old file's permissions (a new one gets 0o644)."""
    mode = path.stat().st_mode & 0o777 if path.exists() else 0o644
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as out:
            out.write(dumps(history))
            out.flush()
            os.fsync(out.fileno())
        os.chmod(tmp, mode)
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise


def problems(value: object) -> list[Problem]:
    """What is wrong with `value` as the `history` param, before a run: nothing for "" (no history)
    or a file not there yet (the first run: it is written at the end) if its folder exists; else
    every problem of the file as `load` finds them."""
    if not isinstance(value, str) or not value:
        return []
    path = Path(value)
    if not path.exists():
        folder = path.parent
        if not folder.is_dir():
            return [(value, 1, 1, f"the history is written at the end of the run, but folder '{folder}' "
                     "does not exist")]
        return []
    try:
        load(path)
    except HistoryError as err:
        return err.problems
    return []


def load(path: Path) -> History:
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise HistoryError([(str(path), 1, 1, f"cannot read the history file: {exc}")]) from None
    return loads(text, str(path))


def loads(text: str, file: str = "<history>") -> History:
    try:
        root = yaml.compose(text, Loader=yaml.SafeLoader)
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        line, col = (mark.line + 1, mark.column + 1) if mark else (1, 1)
        raise HistoryError([(file, line, col, f"not valid JSON: {exc.problem or exc.context}")]) from None
    except yaml.reader.ReaderError as exc:  # a character YAML (and JSON) does not allow
        before = text[: exc.position]
        line, col = before.count("\n") + 1, exc.position - (before.rfind("\n") + 1) + 1
        code = exc.character if isinstance(exc.character, int) else ord(exc.character)
        message = f"not valid JSON: character U+{code:04X} not allowed"
        raise HistoryError([(file, line, col, message)]) from None
    except RecursionError:
        raise HistoryError([(file, 1, 1, "not a history file: lists or objects nested too deep")]) from None
    reader = _Reader(file)
    history = reader.document(root)
    if reader.errors or history is None:
        raise HistoryError(reader.errors or [(file, 1, 1, "the history file is empty")])
    return history


class _Reader:
    def __init__(self, file: str) -> None:
        self.file = file
        self.errors: list[Problem] = []

    def error(self, node: yaml.Node, message: str) -> None:
        self.errors.append((self.file, node.start_mark.line + 1, node.start_mark.column + 1, message))

    def document(self, root: yaml.Node | None) -> History | None:
        if root is None:
            return None
        top = self.mapping(root, {"version", "pairs", "robots"}, {"version"})
        if top is None:
            return None
        if "version" in top:
            version = self.count(top["version"])
            if version is not None and version != VERSION:
                self.error(top["version"], f"unknown history version {version} (this reader knows {VERSION})")
        pairs = self.entries(top.get("pairs"), self.pair_entry, "pair")
        robots = self.entries(top.get("robots"), self.robot_entry, "robot")
        return History(
            pairs=dict(pairs),
            robots={i: r for i, r, _ in robots},
            beliefs={i: b for i, _, b in robots if b is not None},
        )

    def entries(self, node: yaml.Node | None, read: Callable[[yaml.Node], T | None], what: str) -> list[T]:
        if node is None:
            return []
        if not isinstance(node, yaml.SequenceNode):
            self.error(node, f"expected a list of {what} entries")
            return []
        out: list[T] = []
        keys: set[object] = set()
        for item in node.value:
            entry = read(item)
            if entry is None:
                continue
            key = entry[0] if isinstance(entry, tuple) else entry
            if key in keys:
                self.error(item, f"{what} {key} appears twice")
                continue
            keys.add(key)
            out.append(entry)
        return out

    def pair_entry(self, node: yaml.Node) -> tuple[Pair, Record] | None:
        fields = self.mapping(node, {"robots", "n_s", "n_f"}, {"robots", "n_s", "n_f"})
        if fields is None:
            return None
        ids = fields.get("robots")
        n_s, n_f = self.count(fields.get("n_s")), self.count(fields.get("n_f"))
        key: Pair | None = None
        if ids is not None:
            names = self.names(ids)
            if names is not None and (len(names) != 2 or names[0] == names[1]):
                self.error(ids, "a pair names two different robots")
            elif names is not None:
                key = (min(names), max(names))
        if key is None or n_s is None or n_f is None:
            return None
        return key, Record(n_s, n_f)

    def robot_entry(self, node: yaml.Node) -> tuple[str, Record, float | None] | None:
        fields = self.mapping(node, {"id", "n_s", "n_f", "belief"}, {"id", "n_s", "n_f"})
        if fields is None:
            return None
        robot = self.name(fields.get("id"))
        n_s, n_f = self.count(fields.get("n_s")), self.count(fields.get("n_f"))
        belief = self.number(fields["belief"]) if "belief" in fields else None
        if robot is None or n_s is None or n_f is None or ("belief" in fields and belief is None):
            return None
        return robot, Record(n_s, n_f), belief

    def mapping(self, node: yaml.Node, allowed: set[str], required: set[str]) -> dict[str, yaml.Node] | None:
        if not isinstance(node, yaml.MappingNode):
            self.error(node, f"expected an object with {', '.join(sorted(required))}")
            return None
        out: dict[str, yaml.Node] = {}
        for key, value in node.value:
            name = str(key.value)
            if name not in allowed:
                near = difflib.get_close_matches(name, sorted(allowed), n=1)
                self.error(key, f"unknown field {name!r}" + (f"; did you mean {near[0]!r}?" if near else ""))
            elif name in out:
                self.error(key, f"field {name!r} appears twice")
            else:
                out[name] = value
        for name in sorted(required - set(out)):
            self.error(node, f"missing field {name!r}")
        return out

    def name(self, node: yaml.Node | None) -> str | None:
        if node is None:
            return None
        if not isinstance(node, yaml.ScalarNode) or not node.value:
            self.error(node, "expected a robot id (a non-empty string)")
            return None
        return str(node.value)

    def names(self, node: yaml.Node) -> list[str] | None:
        if not isinstance(node, yaml.SequenceNode):
            self.error(node, "expected a list of two robot ids")
            return None
        out = [self.name(item) for item in node.value]
        return [n for n in out if n is not None] if all(n is not None for n in out) else None

    def count(self, node: yaml.Node | None) -> int | None:
        if node is None:
            return None
        value = node.value if isinstance(node, yaml.ScalarNode) and node.style is None else ""
        if not (isinstance(value, str) and value.isascii() and value.isdigit() and len(value) <= 18):
            self.error(node, "expected a whole number >= 0")
            return None
        return int(value)

    def number(self, node: yaml.Node) -> float | None:
        value = node.value if isinstance(node, yaml.ScalarNode) and node.style is None else ""
        try:
            out = float(value)
        except (TypeError, ValueError):
            out = math.nan
        if not math.isfinite(out):
            self.error(node, "expected a finite number")
            return None
        return out
