"""`hfsm-graph`: draw machine files as diagrams, one figure per machine, an overview, a legend.

Everything is loaded, checked and drawn in memory first; files are written only when all succeeded,
each through a temporary file renamed into place, so bad input leaves the output folder untouched.
"""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from hfsm.cli import report
from hfsm.cli.monitor import read_trace
from hfsm.cli.named import machine_path
from hfsm.cli.quiet import stdout_to_stderr
from hfsm.diagram.dot import to_dot
from hfsm.diagram.extract import Sources, machine_figure, overview
from hfsm.diagram.legend import LEGEND, legend
from hfsm.diagram.model import Figure
from hfsm.diagram.overlay import apply, collect
from hfsm.diagram.render import FORMATS, RenderError, render
from hfsm.errors import UsageError, UserError
from hfsm.library import SUFFIXES
from hfsm.load import load
from hfsm.registry import Registry


def _formats(text: str) -> list[str]:
    chosen = [f.strip() for f in text.split(",") if f.strip()]
    bad = [f for f in chosen if f not in FORMATS]
    if bad or not chosen:
        raise argparse.ArgumentTypeError(f"choose from {', '.join(FORMATS)} (comma-separated), not {text!r}")
    return list(dict.fromkeys(chosen))


def _depth(text: str) -> int:
    value = int(text)
    if value < 0:
        raise argparse.ArgumentTypeError("must be 0 or more")
    return value


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="hfsm-graph",
        description="Draw machine files: a figure per machine, the call graph, the legend.",
    )
    p.add_argument("paths", nargs="+", type=Path, metavar="PATH",
                   help="a machine file, a folder of them, or a machine's name (a plug-in's or in --lib)")
    p.add_argument("-o", "--output", type=Path, default=Path("."), metavar="DIR", help="default: .")
    p.add_argument(
        "--format",
        type=_formats,
        default=["svg"],
        metavar="FMT",
        help="svg, png, pdf or dot; several comma-separated (default: svg)",
    )
    p.add_argument("--depth", type=_depth, default=0, metavar="N", help="draw callees inline, N levels down")
    p.add_argument(
        "--trace", type=Path, metavar="FILE.jsonl", help="overlay a run written by hfsm-run --trace"
    )
    p.add_argument(
        "--lib", action="append", type=Path, default=[], metavar="DIR", help="more machine folders"
    )
    p.add_argument("--no-overview", action="store_true", help="no call-graph figure")
    p.add_argument("--no-legend", action="store_true", help="no legend figure")
    p.add_argument(
        "--prune", action="store_true", help="after writing, delete DIR's other files of the chosen formats"
    )
    return p


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return _main(args)
    except UserError as err:
        report.findings(err.findings)
        return 2
    except UsageError as err:
        print(f"hfsm-graph: {err}", file=sys.stderr)
        return 2
    except RenderError as err:
        print(f"hfsm-graph: Graphviz failed: {err}", file=sys.stderr)
        return 1


def _main(args: argparse.Namespace) -> int:
    outputs = draw(args)
    write_all(args.output, outputs)
    print(f"hfsm-graph: wrote {len(outputs)} files to {args.output}", file=sys.stderr)
    if args.prune:
        for stale in sorted(args.output.iterdir()):
            if stale.is_file() and stale.suffix[1:] in args.format and stale.name not in outputs:
                stale.unlink()
                print(f"hfsm-graph: removed {stale}", file=sys.stderr)
    return 0


def draw(args: argparse.Namespace) -> dict[str, bytes]:
    """Every output file's name and bytes, all drawn in memory; raises on bad input."""
    with stdout_to_stderr():
        registry = Registry.discover()
    named = [machine_path(p, args.lib, registry) for p in args.paths]
    figures = _figures(args, machine_files(named), registry)
    link_ext = next((f for f in args.format if f != "dot"), "svg")
    outputs: dict[str, bytes] = {}
    for figure in figures:
        dot = to_dot(figure, link_ext)
        for fmt in args.format:
            outputs[f"{figure.name}.{fmt}"] = render(dot, fmt)
    return outputs


def machine_files(paths: Sequence[Path]) -> list[Path]:
    """The files named, and the machine files of the folders named, sorted by name."""
    files: list[Path] = []
    for path in paths:
        if path.is_dir():
            found = sorted(p for p in path.iterdir() if p.suffix in SUFFIXES and p.is_file())
            if not found:
                print(f"hfsm-graph: no machine files in {path}", file=sys.stderr)
            files += found
        elif path.is_file():
            files.append(path)
        else:
            raise UsageError(f"{path}: no such file or folder")
    return list(dict.fromkeys(files))


def _figures(args: argparse.Namespace, files: list[Path], registry: Registry) -> list[Figure]:
    figures: list[Figure] = []
    names: list[str] = []
    if files:
        loaded = load(files, libs=args.lib, registry=registry)
        src = Sources.from_loaded(loaded, registry)
        names = [mf.name for mf in loaded.roots]
        figures = [machine_figure(n, src, args.depth, names) for n in names]
        if args.trace is not None:
            stats = collect(_read_trace(args.trace), src.machines)
            figures = [apply(f, f.name, stats) for f in figures]
        if not args.no_overview:
            figures.append(overview(src, names, names))
    if not args.no_legend:
        if LEGEND in names:
            print(f"hfsm-graph: a machine is named '{LEGEND}': no legend drawn", file=sys.stderr)
        else:
            figures.append(legend())
    return figures


def _read_trace(path: Path) -> list[dict[str, Any]]:
    try:
        records = read_trace(path)
    except OSError as exc:
        raise UsageError(f"--trace {path}: {exc.strerror or exc}") from exc
    except UsageError as exc:
        raise UsageError(f"--trace {exc}") from None
    if not records:
        raise UsageError(f"--trace {path}: the trace has no records")
    return [r for r in records if r["agent"] is not None]  # the run's own (its flags, the operator's)


def write_all(folder: Path, outputs: dict[str, bytes]) -> None:
    """Write every file through a temporary file in the same folder, renamed into place."""
    try:
        folder.mkdir(parents=True, exist_ok=True)
        for name, data in outputs.items():
            tmp = folder / f".{name}.{os.getpid()}.tmp"
            try:
                tmp.write_bytes(data)
                os.replace(tmp, folder / name)
            except BaseException:
                tmp.unlink(missing_ok=True)
                raise
    except OSError as exc:
        raise UsageError(f"cannot write to {folder}: {exc.strerror or exc}") from exc


def entry() -> None:
    sys.exit(main())
