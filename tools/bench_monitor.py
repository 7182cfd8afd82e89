"""What the monitor costs and how fast its page is (docs/PERFORMANCE.md, the monitor).

    .venv/bin/python tools/bench_monitor.py --report docs/PERFORMANCE.md

(c) `--monitor` on a run's wall time: the same `hfsm-run` with and without it, alternated, medians
    (a team of 16 in world none that chatters, and a simulated trial, no video);
(a) records a second the page keeps up with: a synthetic live feed (records like a 16-robot run's)
    at rising rates, into the page in headless Chromium; the page's lag (records it has not taken
    yet, as seconds of feed) sampled while fed, and how long it takes to catch up once the feed stops;
(b) the page's JS heap over a long feed: an hour of a 16-robot run's records (the rate measured on
    a simulated trial, 13.4 records a second a robot and 2 poses a second), fed as fast as the page
    takes them, the heap read through the DevTools protocol after a garbage collection.
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from tools.docsection import write_section  # noqa: E402

HFSM_RUN = str(Path(sys.executable).parent / "hfsm-run")
CHROMIUM = "/usr/bin/chromium"
ROBOTS = 16
PER_ROBOT = 13.4  # records a simulated second a robot writes (a 2-robot trial: 4300 in 157 s, poses aside)
CHATTER = """\
doc: A team that talks while it works, in world none, for the monitor's benchmark.
params:
  rounds: {type: int, default: 300}
vars: {n: 0}
outcomes: [done]
receives: [hi]
states:
  talk:
    do: send
    with: {message: hi, data: {n: "${vars.n}"}}
    on: {sent: work}
  work:
    do: wait
    with: {seconds: 0.05}
    on: {done: count, hi: count}
  count:
    do: set
    with: {n: "${vars.n + 1}"}
    on: {done: again}
  again:
    choose:
      - if: "vars.n >= params.rounds"
        then: done
      - else: talk
"""


def wall(command: list[str]) -> tuple[float, float]:
    """Wall and CPU seconds (user + system) a run takes (exit 0, or 1 when stopped by --max-time with
    its trace written). CPU time is what a loaded machine cannot blur."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    begin = time.perf_counter()
    done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    if done.returncode not in (0, 1):
        raise SystemExit(f"{' '.join(command)}: exit {done.returncode}")
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    return time.perf_counter() - begin, cpu


def monitor_cost(runs: int, out: Path) -> list[str]:
    chatter = out / "chatter.yaml"
    chatter.write_text(CHATTER)
    agents = ",".join(f"r{i}" for i in range(ROBOTS))
    cases = {
        "world none, 16 agents chattering (300 rounds)": [
            HFSM_RUN, str(chatter), "--world", "none", "--agents", agents, "--quiet"],
        "simulated trial (move_furniture, seed 3, 60 s, no video)": [
            HFSM_RUN, str(ROOT / "machines" / "move_furniture.yaml"), "--seed", "3", "--max-time", "60",
            "--out", str(out), "--no-video", "--quiet", "--progress", "0"],
    }  # fmt: skip
    lines = [f"Load average at the start: {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores.", "",
             "| run | without `--monitor`: wall, CPU | with: wall, CPU | ratio with/without (median of "
             "pairs): wall, **CPU** | same trace |", "|---|---|---|---|---|"]  # fmt: skip
    for name, command in cases.items():
        walls: dict[bool, list[tuple[float, float]]] = {False: [], True: []}
        traces: dict[bool, bytes] = {}
        for _ in range(runs):
            for monitor in (False, True):
                trace = out / f"t{int(monitor)}.jsonl"
                extra = ["--trace", str(trace)] + (["--monitor", "--monitor-hold", "0"] if monitor else [])
                walls[monitor].append(wall([*command, *extra]))
                traces[monitor] = trace.read_bytes()
        off, on = ([statistics.median(w[i] for w in walls[m]) for i in (0, 1)] for m in (False, True))
        ratio = [statistics.median(w[i] / o[i] for w, o in zip(walls[True], walls[False], strict=True))
                 for i in (0, 1)]
        same = traces[True] == traces[False]
        lines.append(f"| {name} | {off[0]:.2f} s, {off[1]:.2f} s | {on[0]:.2f} s, {on[1]:.2f} s "
                     f"| {ratio[0]:.3f}, **{ratio[1]:.3f}** | {same} |")
    return lines


def records(count: int, start_t: float = 0.0, rate: float = ROBOTS * PER_ROBOT) -> list[dict[str, Any]]:
    """`count` records like a 16-robot run's, `rate` a simulated second: states entered and left,
    events, messages, a pose every half second."""
    out: list[dict[str, Any]] = []
    names = [f"r{i}" for i in range(ROBOTS)]
    poses = {n: [0.1 * i, 0.2, 0.0] for i, n in enumerate(names)}
    for i in range(count):
        t = round(start_t + i / rate, 3)
        name = names[i % ROBOTS]
        kind = ("enter", "event", "exit", "enter", "exit", "send", "receive", "event")[i % 8]
        record: dict[str, Any] = {"t": t, "agent": name, "path": ["move_furniture", "leader", f"s{i % 5}"],
                                  "kind": kind}
        if kind == "event":
            record.update(event="done", target="s1", vars={"x": 0.123456, "count": i})
        elif kind == "send":
            record.update(to="others", message="way_cleared", data={"at": [1.0, 2.0]})
        elif kind == "receive":
            record.update(sender=names[(i + 1) % ROBOTS], message="way_cleared", data={"at": [1.0, 2.0]})
        out.append(record)
        if i % int(rate / 2) == 0:
            out.append({"t": t, "agent": "world", "path": [], "kind": "pose", "room": [5.0, 5.0],
                        "tables": [[0, 0, 0, 0.8, 0.5, 0]], "targets": [], "robots": poses})
    return out


class Feed:
    """A live hub, its server, and a thread that offers records at a rate."""

    def __init__(self) -> None:
        from hfsm.monitor.hub import Hub
        from hfsm.monitor.serve import Server

        self.hub = Hub(live=True, size=2_000_000)
        self.hub.offer({"t": 0.0, "agent": "r0", "path": ["move_furniture"], "kind": "enter"})
        self.server = Server(self.hub, {}, "bench")
        self.server.start()
        self.sent = 1

    def run(self, batch: list[dict[str, Any]], rate: float) -> None:
        """Offer `batch` at `rate` records a wall second, in tenths of a second."""
        step = max(1, int(rate / 10))
        begin = time.monotonic()
        for k in range(0, len(batch), step):
            for record in batch[k:k + step]:
                self.hub.offer(record)
            self.sent += len(batch[k:k + step])
            delay = begin + (k + step) / rate - time.monotonic()
            if delay > 0:
                time.sleep(delay)


def page_rates(rates: list[int], seconds: float) -> list[str]:
    from playwright.sync_api import sync_playwright

    lines = ["| feed (records/s) | lag while fed: median, max (s of feed) | catch-up after the feed | "
             "page kept up |", "|---|---|---|---|"]
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=["--headless", "--no-sandbox"])
        for rate in rates:
            feed = Feed()
            page = browser.new_page(viewport={"width": 1400, "height": 900})
            page.goto(feed.server.url)
            page.wait_for_function("window.hfsm && window.hfsm.replay.records.length > 0")
            batch = records(int(rate * seconds), 0.1)
            thread = threading.Thread(target=feed.run, args=(batch, rate))
            thread.start()
            lags = []
            while thread.is_alive():
                shown = page.evaluate("window.hfsm.replay.records.length")
                lags.append(max(0, feed.sent - shown) / rate)
                time.sleep(0.25)
            thread.join()
            stop = time.monotonic()
            page.wait_for_function(f"window.hfsm.replay.records.length >= {feed.sent}", timeout=600_000,
                                   polling=50)
            catch = time.monotonic() - stop
            lines.append(f"| {rate:,} | {statistics.median(lags):.2f}, {max(lags):.2f} | {catch:.2f} s | "
                         f"{'yes' if catch < 1 else 'no'} |")
            print(lines[-1], flush=True)
            page.close()
            feed.server.stop()
        browser.close()
    return lines


def page_heap(hours: float, rate: int) -> list[str]:
    from playwright.sync_api import sync_playwright

    total = int(hours * 3600 * ROBOTS * PER_ROBOT)
    lines = [f"An hour of a 16-robot run: {total:,} records (plus a pose each half second), fed at {rate:,} "
             "records a wall second.", "", "| records on the page | JS heap used (after a GC) |", "|---|---|"]
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=["--headless", "--no-sandbox"])
        feed = Feed()
        page = browser.new_page(viewport={"width": 1400, "height": 900})
        cdp = page.context.new_cdp_session(page)
        page.goto(feed.server.url)
        page.wait_for_function("window.hfsm && window.hfsm.replay.records.length > 0")
        chunk = total // 6
        for k in range(6):
            feed.run(records(chunk, k * chunk / (ROBOTS * PER_ROBOT)), rate)
            page.wait_for_function(f"window.hfsm.replay.records.length >= {feed.sent}", timeout=600_000,
                                   polling=100)
            cdp.send("HeapProfiler.collectGarbage")
            used = cdp.send("Runtime.getHeapUsage")["usedSize"]
            shown = page.evaluate("window.hfsm.replay.records.length")
            lines.append(f"| {shown:,} | {used / 2**20:.0f} MiB |")
            print(lines[-1], flush=True)
        feed.server.stop()
        browser.close()
    return lines


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--runs", type=int, default=5, help="pairs of runs, alternated")
    p.add_argument("--rates", default="1000,10000,30000,100000", help="feeds of the page, records a second")
    p.add_argument("--seconds", type=float, default=5.0, help="how long each feed lasts")
    p.add_argument("--hours", type=float, default=1.0, help="of a 16-robot run, for the heap")
    p.add_argument("--heap-rate", type=int, default=20000, help="records a second of the heap's feed")
    p.add_argument("--skip-runs", action="store_true", help="the page only")
    p.add_argument("--runs-only", action="store_true", help="--monitor's cost only")
    p.add_argument("--report", type=Path)
    args = p.parse_args(argv)
    command = " ".join(["`.venv/bin/python tools/bench_monitor.py", *(argv or sys.argv[1:])]) + "`"
    lines = [f"Command: {command}.", ""]
    with tempfile.TemporaryDirectory() as folder:
        if not args.skip_runs:
            lines += ["`--monitor` on a run's wall time (page served, no browser attached):", "",
                      *monitor_cost(args.runs, Path(folder)), ""]
    if args.runs_only:
        print("\n".join(lines))
        return 0
    lines += ["The page fed live (headless Chromium, the feed and the server in one process):", "",
              *page_rates([int(r) for r in args.rates.split(",")], args.seconds), "",
              *page_heap(args.hours, args.heap_rate)]
    print("\n".join(lines))
    if args.report:
        write_section(args.report, "bench_monitor", lines)
    return 0


if __name__ == "__main__":
    sys.exit(main())
