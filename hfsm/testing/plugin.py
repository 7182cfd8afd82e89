"""The pytest plug-in (entry point `pytest11`): `pytest` collects `*.test.yaml` files, one item a case."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from hfsm.errors import UserError
from hfsm.testing.check import is_test_file, read_test_file
from hfsm.testing.expect import Mismatch
from hfsm.testing.plan import CasePlan
from hfsm.testing.runner import run_case


def pytest_collect_file(parent: pytest.Collector, file_path: Path) -> pytest.Collector | None:
    if is_test_file(file_path):
        collector: BehaviourTestFile = BehaviourTestFile.from_parent(parent, path=file_path)
        return collector
    return None


class BehaviourTestFile(pytest.File):
    def collect(self) -> Iterator[pytest.Item]:
        try:
            plans = read_test_file(self.path)
        except UserError as err:  # shown as the collection error, every finding at its position
            raise self.CollectError(str(err)) from None
        for plan in plans:
            yield BehaviourCase.from_parent(self, name=plan.name, plan=plan)


class CaseFailed(Exception):
    def __init__(self, failures: list[Mismatch]) -> None:
        super().__init__("\n".join(f.format() for f in failures))
        self.failures = failures


class BehaviourCase(pytest.Item):
    def __init__(self, *, plan: CasePlan, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.plan = plan
        # pytest-lsp's run hook reads `funcargs` and, without it, stops the run of any other item
        self.funcargs: dict[str, Any] = {}

    def runtest(self) -> None:
        outcome = run_case(self.plan)
        if outcome.failures:
            raise CaseFailed(outcome.failures)

    def repr_failure(self, excinfo: pytest.ExceptionInfo[BaseException], style: Any = None) -> str:
        if isinstance(excinfo.value, CaseFailed):
            return str(excinfo.value)
        return str(super().repr_failure(excinfo, style))

    def reportinfo(self) -> tuple[Path, int, str]:
        return self.path, self.plan.line - 1, f"behaviour test {self.plan.name}"
