"""`hfsm-run --monitor`: the page served while the run goes, fed by a trace sink that never blocks.

The run writes each record to its trace file and to the hub's bounded queue (`Tee`); the same seed
writes the same trace with or without the monitor. `--realtime K` paces a run to K times real time
(a `Pacer`, before each tick), so that a fast run can be watched; it changes wall time, never a record.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import sys
import time
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from hfsm.load import Loaded
from hfsm.monitor.control import Control
from hfsm.monitor.hub import Hub, MonitorSink
from hfsm.registry import Registry
from hfsm.runtime.breaks import condition_names
from hfsm.trace import Lines, TraceSink

Video = tuple[Path, float]
LATE = 0.5  # seconds a paced run may fall behind (a slow tick) and catch up on
VIDEO_RATE = 5.0  # simulated seconds in a second of video: hfsm-run's, a frame each 0.5 s at 10 fps


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


class LineTee(Tee):
    """A Tee in front of a trace file: the engine's lines go as they are to the sinks that take
    lines (the file, the monitor), read once as records for the others (a video's labels)."""

    def __init__(self, *sinks: TraceSink) -> None:
        super().__init__(*sinks)
        self._lines = Lines()
        self._takers = [s.write_line for s in sinks if hasattr(s, "write_line")]
        self._readers = [s for s in sinks if not hasattr(s, "write_line")]

    def write_line(self, text: str) -> None:
        for take in self._takers:
            take(text)
        if self._readers:
            for line in self._lines.feed(text):
                record = json.loads(line)
                for sink in self._readers:
                    sink.write(record)


class Pacer:
    """Holds each tick back until `speed` times the wall time since the first has passed (the run
    calls `wait` with a tick's time before running it)."""

    def __init__(self, speed: float) -> None:
        if not 0 < speed < float("inf"):
            raise ValueError(f"--realtime takes a positive number, not {speed}")
        self.speed = speed
        self._start: float | None = None

    def wait(self, t: float) -> None:
        now = time.monotonic()
        if self._start is None or self._start + t / self.speed < now - LATE:
            self._start = now - t / self.speed  # at first, and after a pause: no rush to catch up
        ahead = self._start + t / self.speed - now
        if ahead > 0:
            time.sleep(ahead)


class LiveMonitor:
    def __init__(
        self,
        loaded: Loaded,
        registry: Registry,
        title: str,
        port: int,
        control: Control | None = None,
        video: Video | None = None,
    ) -> None:
        from hfsm.monitor.figures import Figures, machine_svgs
        from hfsm.monitor.serve import Server

        self.hub = Hub(live=True)
        self.hub.video_ready = False  # a video is playable once the world has closed it
        self.control = control
        path, rate = video if video is not None else (None, VIDEO_RATE)
        svgs = Figures(make=lambda: machine_svgs(loaded, registry))
        self.server = Server(self.hub, svgs, title, port, path, control=control, video_rate=rate)
        self.sink = MonitorSink(self.hub)

    def start(self) -> None:
        self.server.start()
        print(f"hfsm-run: monitor at {self.server.url}", file=sys.stderr, flush=True)

    def finish(self, hold: float | None) -> None:
        """Keep the page up after the run as asked (its video shown, if the world wrote one), then
        stop serving."""
        from hfsm.monitor import serve

        self.hub.offer(None)
        self.hub.video_ready = True
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
    labels = label_sink() if label_sink is not None and trace is not None else None
    if labels is not None:  # a world without a video to label has none
        extra.append(labels)
    monitor = None
    if args.monitor is not None:
        inputs: Mapping[str, object] = getattr(world, "inputs", dict)()
        names = condition_names((mf.model for mf in loaded.machines.values()), inputs)
        control = Control(args.agent_names, args.breaks, names)
        monitor = LiveMonitor(loaded, registry, title, args.monitor, control, _video(world))
        extra.append(monitor.sink)
    if not extra:
        return trace, None
    if monitor is not None:
        monitor.start()
    kind = LineTee if hasattr(trace, "write_line") else Tee
    return kind(*([trace] if trace is not None else []), *extra), monitor


def _video(world: object) -> Video | None:
    """The video the world writes that a browser plays (MP4, WebM), and its rate (the world's
    `video_rate`, simulated seconds per second of video)."""
    paths = [Path(p) for p in getattr(world, "outputs", ())]
    found = next((p for p in paths if p.suffix in (".mp4", ".webm")), None)
    rate = getattr(world, "video_rate", VIDEO_RATE)
    return (found, float(rate)) if found is not None else None


def finish(args: argparse.Namespace) -> None:
    """The end of a run with `--monitor`: keep its page up as asked, then stop it."""
    monitor: LiveMonitor | None = getattr(args, "live_monitor", None)
    if monitor is not None:
        monitor.finish(args.monitor_hold)


def pacer(args: argparse.Namespace) -> Pacer | None:
    """The run's pace (`--realtime K`), if asked."""
    return Pacer(args.realtime) if args.realtime is not None else None
