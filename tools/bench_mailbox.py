"""CPU microseconds to take one message from behind N others nobody takes, this tree against a revision.

Usage: .venv/bin/python tools/bench_mailbox.py [--rev 308e3ee] [--sizes 100,1000,5000]

A mailbox holds N messages of other names (as a room's do: messages nobody takes stay for the run)
and one `scope/room_alive`; each repeat takes it under the scope and appends it again, for 0.5 s of
CPU time. The revision's `hfsm` is `git archive REV hfsm` unpacked into a temporary folder and put
first on PYTHONPATH of a child process (as tools/bench_before.py does).
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def measure(sizes: list[int]) -> list[float]:
    from hfsm.primitive import Message
    from hfsm.runtime.mailbox import Mailbox

    out = []
    for n in sizes:
        box = Mailbox([Message(f"scope/left{i % 7}", "x", "y", {}, 0) for i in range(n)])
        box.append(Message("scope/room_alive", "x", "y", {}, 0))
        begin, repeats = time.process_time(), 0
        while time.process_time() - begin < 0.5:
            message = box.take(("room_alive",), "scope/")
            assert message is not None
            box.append(message)
            repeats += 1
        out.append((time.process_time() - begin) / repeats * 1e6)
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rev", default="main")
    parser.add_argument("--sizes", default="100,1000,5000")
    parser.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()
    sizes = [int(n) for n in args.sizes.split(",")]
    if args.child:
        print(" ".join(f"{us:.1f}" for us in measure(sizes)))
        return
    with tempfile.TemporaryDirectory() as tmp:
        archive = subprocess.run(["git", "-C", str(ROOT), "archive", args.rev, "hfsm"], capture_output=True,
                                 check=True).stdout
        subprocess.run(["tar", "-x", "-C", tmp], input=archive, check=True)
        rows = {}
        for label, path in ((args.rev, tmp), ("this tree", str(ROOT))):
            env = dict(os.environ, PYTHONPATH=path)
            done = subprocess.run([sys.executable, __file__, "--child", "--sizes", args.sizes], env=env,
                                  capture_output=True, text=True, check=True)
            rows[label] = done.stdout.split()
    print("| messages ahead | " + " | ".join(f"{label}: us a take" for label in rows) + " |")
    print("|---:|" + "---:|" * len(rows))
    for i, n in enumerate(sizes):
        print(f"| {n:,} | " + " | ".join(values[i] for values in rows.values()) + " |")


if __name__ == "__main__":
    main()
