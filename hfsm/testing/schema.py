"""The JSON Schema of behaviour-test files, for editors (yaml-language-server)."""

from __future__ import annotations

from hfsm.schema import schema_text as _schema_text
from hfsm.testing.model import TestFile


def schema_text() -> str:
    return _schema_text(TestFile)
