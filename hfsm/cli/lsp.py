"""`hfsm-lsp`: the language server of machine and test files, over stdio (docs/EDITORS.md)."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence


def main(argv: Sequence[str] | None = None) -> int:
    argparse.ArgumentParser(
        prog="hfsm-lsp",
        description="A language server for hfsm machine files and behaviour-test files, on stdin/stdout. "
        "Editors start it themselves: see docs/EDITORS.md.",
    ).parse_args(argv)
    from hfsm.lsp.server import main as serve

    serve()
    return 0


def entry() -> None:
    sys.exit(main())


if __name__ == "__main__":
    entry()
