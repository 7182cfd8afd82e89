"""Guards of the command line: numbers in range, outputs that are not inputs, signals that stop a run.

Exit codes: 2 when the input or an argument is wrong, an output that cannot be created included
(found before the run: nothing is written); 1 when the run fails, or writing its results fails
while it runs or as it ends (a full disk); 128 + N when signal N stopped it (130 for Ctrl-C).
"""

from __future__ import annotations

import argparse
import math
import os
import signal
import stat
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from types import FrameType
from typing import TYPE_CHECKING, Any

from hfsm.errors import UsageError

if TYPE_CHECKING:
    from hfsm.world import World


class OutputError(Exception):
    """Writing a result failed after the run began (a full disk): exit 1."""


def number(low: float, high: float, *, integer: bool = False, above: bool = False) -> Callable[[str], Any]:
    """An argparse type: a finite number in [low, high] ((low, high] when `above`)."""

    def parse(text: str) -> float | int:
        try:
            value: float | int = int(text) if integer else float(text)
        except ValueError:
            kind = "a whole number" if integer else "a number"
            raise argparse.ArgumentTypeError(f"{text!r} is not {kind}") from None
        low_ok = value > low if above else value >= low
        if not (math.isfinite(value) and low_ok and value <= high):
            bound = f"more than {low:g}" if above else f"at least {low:g}"
            message = f"takes a finite number {bound} and at most {high:g}, not {text}"
            raise argparse.ArgumentTypeError(message)
        return value

    return parse


SEED = number(0, 2**63 - 1, integer=True)
DT = number(0.001, 10.0)
MAX_TIME = number(0, 1e9, above=True)


def same_file(a: Path, b: Path) -> bool:
    try:
        return os.path.samefile(a, b)
    except OSError:
        return a.resolve() == b.resolve()


def check_outputs(outputs: Iterable[tuple[str, Path]], inputs: Iterable[Path]) -> None:
    """Refuse an output that is an input, two outputs onto one file, and a video onto a device."""
    inputs = [p for p in inputs if p.exists()]
    seen: list[tuple[str, Path]] = []
    for flag, path in outputs:
        for source in inputs:
            if same_file(path, source):
                raise UsageError(f"{flag} {path} would overwrite an input file ({source})")
        for other_flag, other in seen:
            if path.resolve() == other.resolve():
                raise UsageError(f"{flag} and {other_flag} both name {path}")
        if path.exists() and path.is_dir():
            raise UsageError(f"{flag} {path} is a folder, not a file")
        seen.append((flag, path))


def is_regular_or_new(path: Path) -> bool:
    """A regular file, or nothing yet (a folder on the way that is a file is left to make_folder)."""
    try:
        return stat.S_ISREG(path.stat().st_mode)
    except (FileNotFoundError, NotADirectoryError):
        return True
    except OSError:
        return False


def make_folder(folder: Path, flag: str) -> None:
    try:
        folder.mkdir(parents=True, exist_ok=True)
        if not folder.is_dir():
            raise NotADirectoryError(20, "it is a file, not a folder")
    except OSError as exc:
        raise UsageError(f"{flag}: cannot write in {folder}: {exc.strerror or exc}") from None


# --- signals ---------------------------------------------------------------------------------


@dataclass
class StopFlag:
    signum: int | None = None

    @property
    def exit_code(self) -> int:
        return 128 + (self.signum or signal.SIGINT)

    @property
    def name(self) -> str:
        return signal.Signals(self.signum or signal.SIGINT).name


STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM)


@contextmanager
def signals_raise() -> Iterator[None]:
    """Outside a run, SIGTERM stops the command like Ctrl-C (KeyboardInterrupt: exit 130 + no traceback)."""

    def handler(signum: int, frame: FrameType | None) -> None:
        raise KeyboardInterrupt(signum)

    with _handlers(handler):
        yield


@contextmanager
def signals_flag(flag: StopFlag) -> Iterator[None]:
    """During a run, the first signal asks the run to stop at the next tick; a second one at once."""

    def handler(signum: int, frame: FrameType | None) -> None:
        if flag.signum is not None:
            raise KeyboardInterrupt(signum)
        flag.signum = signum

    with _handlers(handler):
        yield


@contextmanager
def _handlers(handler: Callable[[int, FrameType | None], None]) -> Iterator[None]:
    try:
        saved = {s: signal.signal(s, handler) for s in STOP_SIGNALS}
    except ValueError:  # not the main thread: leave the signals alone
        yield
        return
    try:
        yield
    finally:
        for s, old in saved.items():
            signal.signal(s, old)


def close_world(world: World) -> list[str]:
    """Close the world (it finishes its video and picture); a failed write is an OutputError."""
    try:
        return world.close()
    except OSError as exc:
        raise OutputError(f"cannot write the world's files: {exc.strerror or exc}") from None
