"""A picture of the monitor's navigation (breadcrumb, find, timeline marks, a figure full size) on a
replay of examples/ping_pong.yaml (docs/MONITOR.md).

    .venv/bin/python tools/monitor_nav_shot.py -o docs/figures/monitor-nav.png  (and monitor-nav-full.png)
"""

from __future__ import annotations

import argparse
import tempfile
from pathlib import Path

from playwright.sync_api import sync_playwright

from hfsm.cli.monitor import drawings, read_trace
from hfsm.cli.run import main as run_main
from hfsm.monitor.hub import Hub
from hfsm.monitor.serve import Server

ROOT = Path(__file__).resolve().parents[1]
MACHINE = ROOT / "examples" / "ping_pong.yaml"
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run"]


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("-o", "--output", type=Path, required=True)
    args = p.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        trace = Path(folder) / "pp.jsonl"
        assert run_main([str(MACHINE), "--agents", "a,b", "--trace", str(trace), "--quiet"]) == 0
        server = Server(Hub(read_trace(trace)), drawings(MACHINE, []), trace.name)
        server.start()
        try:
            with sync_playwright() as pw:
                browser = pw.chromium.launch(executable_path="/usr/bin/chromium", args=FLAGS)
                page = browser.new_page(viewport={"width": 1300, "height": 640})
                page.goto(server.url)
                page.wait_for_function("window.hfsm && window.hfsm.replay.records.length > 0")
                page.evaluate("window.hfsm.seek(0.05)")
                page.fill("#search", "rec")
                page.evaluate("window.scrollTo(0, 0)")
                page.screenshot(path=str(args.output))
                page.click('.agent[data-agent="b"] .drawing button.enlarge')
                page.screenshot(path=str(args.output.with_name(args.output.stem + "-full.png")))
                browser.close()
        finally:
            server.stop()
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
