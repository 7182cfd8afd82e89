"""A picture of the monitor's operator panel on a live run that holds an arc (docs/MONITOR.md).

    .venv/bin/python tools/monitor_controls_shot.py -o docs/figures/monitor-controls.png
"""

from __future__ import annotations

import argparse
import subprocess
import sys
from pathlib import Path

from playwright.sync_api import sync_playwright

ROOT = Path(__file__).resolve().parents[1]
MACHINE = ROOT / "tests" / "monitor" / "data" / "operated.yaml"
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run"]


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("-o", "--output", type=Path, required=True)
    args = p.parse_args()
    run = subprocess.Popen(
        [sys.executable, "-m", "hfsm.cli.run", str(MACHINE), "--autonomy", "low", "--realtime", "1",
         "--monitor", "--monitor-hold", "0", "--quiet", "--trace", "/dev/null"],
        stderr=subprocess.PIPE, text=True)  # fmt: skip
    assert run.stderr is not None
    line = ""
    while "monitor at" not in line:
        line = run.stderr.readline()
    url = line.split("monitor at ", 1)[1].strip()
    try:
        with sync_playwright() as pw:
            browser = pw.chromium.launch(executable_path="/usr/bin/chromium", args=FLAGS)
            page = browser.new_page(viewport={"width": 1300, "height": 640})
            page.goto(url)
            page.wait_for_function("document.getElementById('op-held').textContent.includes('holds')")
            page.fill("#op-break", "enter:listen")
            page.click("#op-add-break")
            page.wait_for_function("document.getElementById('op-breaks').textContent.includes('listen')")
            page.screenshot(path=str(args.output))
            browser.close()
    finally:
        run.kill()
        run.wait()
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
