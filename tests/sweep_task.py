"""A cheap, seeded, world-free task for sweep tests; importable by spawned and Dask workers."""

from __future__ import annotations

import hashlib
import io
import json
from contextlib import redirect_stdout
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent


def run_example(spec: dict[str, Any]) -> dict[str, Any]:
    """Run examples/ping_pong.yaml under world none for a seed; the result and a digest of it."""
    from hfsm.cli.run import main

    out = io.StringIO()
    with redirect_stdout(out):
        code = main([str(ROOT / "examples" / spec["example"]), "--world", "none", "--json", "--quiet",
                     "--seed", str(spec["seed"])])
    result = json.loads(out.getvalue())
    return {"spec": spec, "code": code, "result": result,
            "digest": hashlib.sha256(out.getvalue().encode()).hexdigest()}
