"""A real editor: Neovim from Debian's packages, headless, starts `hfsm-lsp` for a machine file with
errors (the set-up of docs/EDITORS.md) and gets the diagnostics `hfsm-run --check` gives."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
NVIM = shutil.which("nvim")


def test_neovim_shows_the_servers_diagnostics(tmp_path: Path) -> None:
    if NVIM is None:
        pytest.fail("Neovim is not installed: `make test` installs it (apt-get install neovim)")
    out = tmp_path / "diagnostics.json"
    server = Path(sys.executable).parent / "hfsm-lsp"
    env = {**os.environ, "HFSM_LSP": str(server), "HFSM_WORLD": "none"}
    command = [
        NVIM, "--headless", "--clean", "-u", str(HERE / "nvim" / "init.lua"), "broken.yaml",
        "-c", f"lua HfsmWriteDiagnostics('{out}')", "-c", "qa!",
    ]  # fmt: skip
    subprocess.run(command, cwd=HERE / "data", env=env, timeout=180, check=True, capture_output=True)
    found = [tuple(d) for d in json.loads(out.read_text())]
    assert sorted(found) == [
        (3, 8, 12, "E300", 1, "unknown behaviour 'wiat'; did you mean 'wait'?"),
        (4, 4, 11, "E200", 1, "unknown key 'timeout'; did you mean 'timer'?"),
        (5, 15, 20, "E301", 1, "unknown target 'fnish': not a state or outcome; did you mean 'finish'?"),
    ]
