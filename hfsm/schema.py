"""JSON Schemas of the files people write (machine files, behaviour-test files), for editors
(yaml-language-server)."""

from __future__ import annotations

import json
from typing import Any

from pydantic import BaseModel

from hfsm.model import Machine


def schema_of(model: type[BaseModel]) -> dict[str, Any]:
    schema = model.model_json_schema(by_alias=True)
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    return schema


def schema_text(model: type[BaseModel] = Machine) -> str:
    return json.dumps(schema_of(model), indent=2, sort_keys=True) + "\n"
