"""`hfsm-run --monitor`: the page served while the run goes, fed by a trace sink that never blocks.

The run writes each record to its trace file and to the hub's bounded queue (`Tee`); the same seed
writes the same trace with or without the monitor. `--realtime K` paces a run to K times real time
(a `Pacer` sink), so that a fast run can be watched; it changes wall time, never a record.
"""

from __future__ import annotations

import argparse
import contextlib
import sys
import time
from typing import Any

from hfsm.load import Loaded
from hfsm.monitor.control import Control
from hfsm.monitor.hub import Hub, MonitorSink
from hfsm.registry import Registry
from hfsm.trace import TraceSink


def add_arguments(p: argparse.ArgumentParser) -> None:
    group = p.add_argument_group("monitor")
    group.add_argument(
        "--monitor",
        nargs="?",
        const=0,
        type=int,
        metavar="PORT",
        help="serve a live page of the run on 127.0.0.1 (default: any free port)",
    )
    group.add_argument(
        "--monitor-hold",
        type=_seconds,
        metavar="S",
        help="after the run, keep the page up S seconds (default: until Ctrl-C on a "
        "terminal, else not at all)",
    )
    group.add_argument(
        "--realtime",
        type=_speed,
        metavar="K",
        help="pace the run to K times real time, to watch it (default: as fast as it goes)",
    )


def _float(text: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"takes a number, not {text!r}") from None


def _seconds(text: str) -> float:
    value = _float(text)
    if not 0 <= value < float("inf"):
        raise argparse.ArgumentTypeError(f"takes a number of seconds >= 0, not {text!r}")
    return value


def _speed(text: str) -> float:
    value = _float(text)
    if not 0 < value < float("inf"):
        raise argparse.ArgumentTypeError(f"takes a positive, finite speed-up, not {text!r}")
    return value


class Tee:
    """One trace sink that writes to several."""

    def __init__(self, *sinks: TraceSink) -> None:
        self.sinks = sinks

    def write(self, record: dict[str, Any]) -> None:
        for sink in self.sinks:
            sink.write(record)

    def flush(self) -> None:
        for sink in self.sinks:
            sink.flush()

    def close(self) -> None:
        for sink in self.sinks:
            sink.close()


class Pacer:
    """Holds each tick back until `speed` times the wall time since the first has passed."""

    def __init__(self, speed: float) -> None:
        if not 0 < speed < float("inf"):
            raise ValueError(f"--realtime takes a positive number, not {speed}")
        self.speed = speed
        self._start: float | None = None
        self._t = 0.0

    def write(self, record: dict[str, Any]) -> None:
        self._t = float(record.get("t", self._t))

    def flush(self) -> None:
        now = time.monotonic()
        if self._start is None:
            self._start = now - self._t / self.speed
        ahead = self._start + self._t / self.speed - now
        if ahead > 0:
            time.sleep(ahead)

    def close(self) -> None:
        pass


class LiveMonitor:
    def __init__(
        self, loaded: Loaded, registry: Registry, title: str, port: int, control: Control | None = None
    ) -> None:
        from hfsm.monitor.figures import machine_svgs
        from hfsm.monitor.serve import Server

        self.hub = Hub(live=True)
        self.control = control
        self.server = Server(self.hub, machine_svgs(loaded, registry), title, port, control=control)
        self.sink = MonitorSink(self.hub)

    def start(self) -> None:
        self.server.start()
        print(f"hfsm-run: monitor at {self.server.url}", file=sys.stderr, flush=True)

    def finish(self, hold: float | None) -> None:
        """Keep the page up after the run as asked, then stop serving."""
        from hfsm.monitor import serve

        self.hub.offer(None)
        if hold is None:
            hold = float("inf") if sys.stdin.isatty() else 0.0
        if hold > 0:
            shown = "until Ctrl-C" if hold == float("inf") else f"for {hold:g} s"
            print(f"hfsm-run: the run has ended; the monitor stays up {shown}", file=sys.stderr, flush=True)
            with contextlib.suppress(KeyboardInterrupt):
                serve.hold(hold)
        self.server.stop()


def sinks(
    args: argparse.Namespace,
    trace: TraceSink | None,
    loaded: Loaded,
    registry: Registry,
    title: str,
    world: object,
) -> tuple[TraceSink | None, LiveMonitor | None]:
    """The run's trace sink with the monitor, the pacer and the world's own reader (a video's
    labels) added as asked; and the monitor."""
    extra: list[TraceSink] = []
    label_sink = getattr(world, "label_sink", None)
    if label_sink is not None and trace is not None:
        extra.append(label_sink())
    monitor = None
    if args.monitor is not None:
        control = Control(args.agent_names, args.breaks)
        monitor = LiveMonitor(loaded, registry, title, args.monitor, control)
        extra.append(monitor.sink)
    if args.realtime is not None:
        extra.append(Pacer(args.realtime))
    if not extra:
        return trace, None
    if monitor is not None:
        monitor.start()
    return Tee(*([trace] if trace is not None else []), *extra), monitor
