"""`hfsm-test`: run behaviour tests (`*.test.yaml`), world-free and in process (docs/TESTING.md)."""

from __future__ import annotations

import argparse
import sys
import time
from collections.abc import Sequence
from pathlib import Path

from hfsm.cli import report
from hfsm.errors import Finding, UserError
from hfsm.testing.check import find_test_files, read_test_file
from hfsm.testing.plan import CasePlan
from hfsm.testing.runner import run_case
from hfsm.testing.schema import schema_text


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="hfsm-test",
        description="Run behaviour tests: *.test.yaml files, or the folders holding them.",
        epilog="Exit 0: all passed. 1: a test failed. 2: a bad test file or argument; nothing ran.",
    )
    p.add_argument("paths", nargs="*", type=Path, metavar="PATH", help="test files or folders")
    p.add_argument("-k", dest="keyword", metavar="TEXT", help="only the cases whose name holds TEXT")
    p.add_argument("-v", "--verbose", action="store_true", help="name every case, passed or not")
    p.add_argument("--schema", action="store_true", help="print the JSON Schema of test files")
    return p


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    if args.schema:
        sys.stdout.write(schema_text())
        return 0
    if not args.paths:
        print("hfsm-test: give test files or folders (or --schema)", file=sys.stderr)
        return 2
    plans, findings = _check(args.paths)
    if findings:
        report.findings(findings)
        return 2
    chosen = [p for p in plans if args.keyword is None or args.keyword in p.name]
    return _run(chosen, verbose=args.verbose)


def _check(paths: list[Path]) -> tuple[list[CasePlan], list[Finding]]:
    """Every case of every file, checked; or every problem of every file."""
    plans: list[CasePlan] = []
    findings: list[Finding] = []
    for path in paths:
        if not path.exists():
            findings.append(Finding(str(path), 1, 1, "T100", "no such file or folder"))
    files = find_test_files([p for p in paths if p.exists()])
    if not files and not findings:
        findings.append(Finding(str(paths[0]), 1, 1, "T100", "no *.test.yaml files here"))
    for file in files:
        try:
            plans.extend(read_test_file(file))
        except UserError as err:
            findings.extend(err.findings)
    return plans, findings


def _run(plans: list[CasePlan], *, verbose: bool) -> int:
    start = time.perf_counter()
    failed = 0
    for plan in plans:
        outcome = run_case(plan)
        name = f"{plan.file}::{plan.name}"
        if outcome.passed:
            if verbose:
                print(f"PASS {name}")
            continue
        failed += 1
        print(f"FAIL {name}")
        for failure in outcome.failures:
            print(f"  {failure.format()}")
    seconds = time.perf_counter() - start
    sys.stdout.flush()
    files = len({p.file for p in plans})
    print(
        f"{len(plans) - failed} passed, {failed} failed "
        f"({len(plans)} cases in {files} files, {seconds:.2f} s)",
        file=sys.stderr,
    )
    return 1 if failed else 0


def entry() -> None:
    sys.exit(main())
