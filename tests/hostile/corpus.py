"""Hostile files of every kind a command reads: machine files, behaviour tests, scenarios, history files
and traces. Each case is made in a folder at test time (a 50 MB file is not kept in the repository).

A case is (kind, file name, what to write): bytes, or None for cases made by `make_special`.
"""

from __future__ import annotations

import os
import random
from collections.abc import Callable
from pathlib import Path

BIG = "9" * 400
RUN = "outcomes: [done]\nstates:\n  a: {do: wait, with: {seconds: 1}, on: {done: done}}\n"
TEST = "machine: hello\ntests:\n  t:\n"
SCENE = "task: table_to_wall\nroom: {width: 5.0, depth: 5.0}\ntable: {x: 0, y: 0, yaw: 0, length: 0.8, width: 0.5}\n"
ROBOTS = "robots:\n  r1: {x: 0.3, y: -1.2, yaw: 45}\n  r2: {x: -0.3, y: 1.2, yaw: -135}\n"
HISTORY = '{"version": 1, "pairs": [], "robots": [%s]}\n'
RECORD = '{"t": 0, "agent": "robot", "path": ["hello"], "event": "enter"}\n'


def _garbage(seed: int, size: int) -> bytes:
    return random.Random(seed).randbytes(size)


def _laughs(levels: int = 9) -> str:
    lines = ['a0: &a0 ["lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol"]']
    for i in range(1, levels + 1):
        lines.append(f"a{i}: &a{i} [" + ", ".join([f"*a{i - 1}"] * 10) + "]")
    return "\n".join(lines) + "\n"


def _deep_blocks(depth: int) -> str:
    return "".join(" " * i + f"k{i}:\n" for i in range(depth)) + " " * depth + "x\n"


MACHINES: dict[str, bytes | str] = {
    "garbage.yaml": _garbage(1, 4096),
    "garbage_big.yaml": _garbage(2, 2_000_000),
    "bom_only.yaml": "\ufeff",
    "bom_then_garbage.yaml": b"\xef\xbb\xbf" + _garbage(3, 300),
    "nul_bytes.yaml": RUN.replace("seconds: 1", "seconds: 1\x00\x00"),
    "not_utf8.yaml": RUN.encode() + b"x: \xff\xfe\n",
    "utf16.yaml": RUN.encode("utf-16"),
    "empty.yaml": "",
    "comments_only.yaml": "# nothing\n# at all\n",
    "top_list.yaml": "- a\n- b\n",
    "top_scalar.yaml": "just text\n",
    "tabs.yaml": "outcomes: [done]\nstates:\n\ta: {do: wait, on: {done: done}}\n",
    "bidi_names.yaml": RUN.replace("a:", "a\u202e\u200b:"),
    "emoji_names.yaml": RUN.replace("  a:", "  \U0001f916:").replace("[done]", "[\U0001f389]"),
    "lone_surrogate.yaml": RUN.encode() + b"x: \xed\xa0\x80\n",
    "crlf.yaml": RUN.replace("\n", "\r\n") + "timer: x\r\n",
    "cr_only.yaml": (RUN + "timer: x\n").replace("\n", "\r"),
    "billion_laughs.yaml": _laughs() + RUN,
    "laughs_in_states.yaml": RUN + "vars: " + "{" + ", ".join(f"v{i}: *a9" for i in range(3)) + "}\n"
    + _laughs(),
    "deep_blocks.yaml": _deep_blocks(3000),
    "deep_flow.yaml": "outcomes: " + "[" * 200_000 + "]" * 200_000 + "\n",
    "deep_flow_maps.yaml": "vars: " + "{a: " * 50_000 + "1" + "}" * 50_000 + "\n",
    "unclosed_flow.yaml": "outcomes: " + "[" * 5000 + "\n",
    "many_nodes.yaml": "vars: {v: [" + "1, " * 1_100_000 + "1]}\n" + RUN,
    "long_line.yaml": "doc: " + "a" * 6_000_000 + "\n" + RUN + "timer: x\n",
    "long_state_name.yaml": RUN.replace("  a:", "  " + "a" * 100_000 + ":"),
    "timer_400_digits.yaml": RUN + f"timer: {BIG}\n",
    "wait_400_digits.yaml": RUN.replace("seconds: 1", f"seconds: {BIG}"),
    "float_param_400_digits.yaml": RUN.replace("seconds: 1", "seconds: '${params.s}'")
    + f"params:\n  s: {{type: float, default: {BIG}}}\n",
    "int_5000_digits.yaml": RUN + "vars: {x: " + "7" * 5000 + "}\n",
    "timer_inf.yaml": RUN + "timer: 1e400\n",
    "timer_nan.yaml": RUN + "timer: .nan\n",
    "wait_negative_inf.yaml": RUN.replace("seconds: 1", "seconds: -.inf"),
    "key_list.yaml": RUN + "vars:\n  ? [a, b]\n  : 1\n",
    "key_mapping.yaml": RUN + "vars:\n  ? {a: 1}\n  : 2\n",
    "key_int.yaml": RUN.replace("  a:", "  1:"),
    "key_null.yaml": RUN + "vars: {null: x}\n",
    "key_bool.yaml": RUN.replace("on: {done: done}", "on: {true: done}"),
    "alias_cycle.yaml": "a: &x [*x]\n",
    "two_documents.yaml": RUN + "---\n" + RUN,
    "h61 Bad-Name.yaml": RUN,
    "Upper.yaml": RUN,
    "yaml_tags.yaml": RUN + "vars: {x: !!python/object/apply:os.system ['true']}\n",
}

TESTS: dict[str, bytes | str] = {
    "garbage.test.yaml": _garbage(4, 5000),
    "key_list.test.yaml": TEST + "    expect:\n      ? [a, b]\n      : 1\n",
    "key_int.test.yaml": TEST.replace("  t:", "  1:") + "    expect: {outcome: done}\n",
    "at_400_digits.test.yaml": TEST + f"    messages: [{{at: {BIG}, from: r1, message: m}}]\n"
    + f"    expect: {{outcome: done, time: {BIG}}}\n",
    "at_nan.test.yaml": TEST + "    messages: [{at: .nan, from: r1, message: m}]\n    expect: {time: -.inf}\n",
    "laughs.test.yaml": _laughs() + TEST + "    expect: {outcome: done}\n",
    "deep.test.yaml": TEST + "    expect: {outputs: " + "[" * 100_000 + "]" * 100_000 + "}\n",
}

SCENARIOS: dict[str, bytes | str] = {
    "garbage.scenario.yaml": _garbage(5, 3000),
    "nan.scenario.yaml": SCENE.replace("width: 5.0", "width: .nan") + ROBOTS,
    "negative.scenario.yaml": SCENE.replace("length: 0.8", "length: -0.8").replace("depth: 5.0", "depth: -5")
    + ROBOTS,
    "huge_numbers.scenario.yaml": SCENE.replace("x: 0,", f"x: {BIG},") + ROBOTS.replace("yaw: 45", "yaw: 1e400"),
    "key_list.scenario.yaml": SCENE + ROBOTS + "? [a, b]\n: 1\n",
    "key_int.scenario.yaml": SCENE + "robots:\n  1: {x: 0.3, y: -1.2, yaw: 45}\n",
    "laughs.scenario.yaml": _laughs() + SCENE + ROBOTS,
    "no_robots.scenario.yaml": SCENE + "robots: {}\n",
}

HISTORIES: dict[str, bytes | str] = {
    "garbage.json": _garbage(6, 3000),
    "deep.json": "[" * 100_000 + "]" * 100_000 + "\n",
    "deep_objects.json": '{"a": ' * 5000 + "1" + "}" * 5000 + "\n",
    "key_list.json": '{"version": 1, ? [a, b]: 1}\n',
    "key_int.json": '{"version": 1, 1: 2}\n',
    "huge.json": HISTORY % f'{{"id": "r1", "n_s": {BIG}, "n_f": 0, "belief": {BIG}}}',
    "nan.json": HISTORY % '{"id": "r1", "n_s": 1, "n_f": 0, "belief": .nan}',
    "laughs.json": _laughs(),
}

TRACES: dict[str, bytes | str] = {
    "garbage.jsonl": _garbage(7, 3000),
    "empty.jsonl": "",
    "not_objects.jsonl": "[1, 2]\n3\n",
    "deep.jsonl": "[" * 100_000 + "]" * 100_000 + "\n",
    "deep_record.jsonl": '{"path": ["hello"], "x": ' + "[" * 50_000 + "]" * 50_000 + "}\n",
    "huge_int.jsonl": '{"path": ["hello"], "t": ' + "9" * 5000 + "}\n",
    "nan.jsonl": '{"path": ["hello"], "t": NaN, "agent": "robot"}\n',
    "path_not_list.jsonl": '{"path": "hello"}\n',
    "cut_last_line.jsonl": RECORD + RECORD[:30],
    "no_machine.jsonl": '{"path": []}\n',
    "bad_record_fields.jsonl": '{"path": [1, {"a": 2}], "t": "x", "agent": []}\n',
}


def write(folder: Path, name: str, content: bytes | str) -> Path:
    path = folder / name
    path.write_bytes(content if isinstance(content, bytes) else content.encode("utf-8", "surrogatepass"))
    return path


def _fifo(folder: Path) -> Path:
    path = folder / "fifo.yaml"
    os.mkfifo(path)
    return path


def _folder(folder: Path) -> Path:
    path = folder / "folder.yaml"
    path.mkdir()
    return path


def _loop(folder: Path) -> Path:
    path = folder / "loop.yaml"
    path.symlink_to(path)
    return path


def _dangling(folder: Path) -> Path:
    path = folder / "dangling.yaml"
    path.symlink_to(folder / "nowhere.yaml")
    return path


def _huge(folder: Path) -> Path:
    path = folder / "fifty_mb.yaml"
    with path.open("wb") as out:
        out.write(RUN.encode())
        for _ in range(50):
            out.write(b"# " + b"x" * (1 << 20) + b"\n")
    return path


SPECIAL: dict[str, Callable[[Path], Path]] = {
    "fifo": _fifo, "folder": _folder, "symlink_loop": _loop, "dangling_symlink": _dangling, "fifty_mb": _huge,
}
