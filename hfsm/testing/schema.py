"""The JSON Schema of behaviour-test files, for editors (yaml-language-server)."""

from __future__ import annotations

import json
from typing import Any

from hfsm.testing.model import TestFile


def schema() -> dict[str, Any]:
    body = TestFile.model_json_schema(by_alias=True)
    body["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    return body


def schema_text() -> str:
    return json.dumps(schema(), indent=2, sort_keys=True) + "\n"
