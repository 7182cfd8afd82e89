"""The JSON Schema of machine files, for editors (yaml-language-server)."""

from __future__ import annotations

import json
from typing import Any

from hfsm.model import Machine


def machine_schema() -> dict[str, Any]:
    schema = Machine.model_json_schema(by_alias=True)
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    return schema


def schema_text() -> str:
    return json.dumps(machine_schema(), indent=2, sort_keys=True) + "\n"
