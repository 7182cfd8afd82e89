"""A picture of the monitor for the README: the page over a trace, at a chosen time, in Chromium.

    .venv/bin/python tools/monitor_shot.py TRACE.jsonl --at 60 -o docs/figures/monitor.png [--lib DIR]
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from hfsm.cli.monitor import replay  # noqa: E402
from hfsm.monitor.hub import Hub  # noqa: E402
from hfsm.monitor.serve import Server  # noqa: E402

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--no-first-run"]


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("trace", type=Path)
    p.add_argument("--at", type=float, default=0.0, help="the time shown (s)")
    p.add_argument("-o", "--output", type=Path, required=True)
    p.add_argument("--lib", action="append", type=Path, default=[])
    p.add_argument("--width", type=int, default=1600)
    args = p.parse_args(argv)
    records, svgs = replay(args.trace, args.lib)
    server = Server(Hub(records), svgs, args.trace.name)
    server.start()
    from playwright.sync_api import sync_playwright

    try:
        with sync_playwright() as pw:
            browser = pw.chromium.launch(executable_path="/usr/bin/chromium", args=FLAGS)
            page = browser.new_page(viewport={"width": args.width, "height": 1000})
            page.goto(server.url)
            page.wait_for_function("window.hfsm && window.hfsm.replay.records.length > 0")
            page.evaluate(f"window.hfsm.seek({args.at})")
            args.output.parent.mkdir(parents=True, exist_ok=True)
            page.screenshot(path=str(args.output), full_page=False)
            browser.close()
    finally:
        server.stop()
    print(f"wrote {args.output}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
