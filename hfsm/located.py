"""Validate a located YAML document against a pydantic model; every error at its line and column."""

from __future__ import annotations

import types
from typing import Annotated, Any, TypeVar, Union, get_args, get_origin

from pydantic import BaseModel, Tag, ValidationError
from pydantic.fields import FieldInfo
from pydantic_core import ErrorDetails

from hfsm.errors import Finding, UserError
from hfsm.expr import reads
from hfsm.names import NAME_PATTERN, did_you_mean
from hfsm.spec import shown
from hfsm.yamlio import Document, Path_

M = TypeVar("M", bound=BaseModel)

_TYPE_NAMES = {
    "float_type": "a number",
    "int_type": "a whole number",
    "string_type": "a string",
    "bool_type": "true or false",
    "dict_type": "a mapping",
    "list_type": "a list",
    "model_type": "a mapping",
    "model_attributes_type": "a mapping",
}


def validate(model: type[M], doc: Document) -> M:
    try:
        return model.model_validate(doc.data)
    except ValidationError as exc:
        raise UserError(findings(model, doc, exc.errors())) from None


def findings(model: type[BaseModel], doc: Document, errors: list[ErrorDetails]) -> list[Finding]:
    """One finding per located value: a union's alternatives fail together but read as one."""
    seen: set[tuple[Path_, bool, object]] = set()
    out: list[Finding] = []
    misspelt = _misspelt(model, doc, errors)
    swaps = _swaps(doc, errors)
    for err in errors:
        if err["type"] == "missing" and data_path(doc.data, err["loc"])[0] in misspelt | set(swaps):
            continue  # `els:` for `else:`: the unknown key says it, with the key it meant
        path, is_key = data_path(doc.data, err["loc"])
        is_key = is_key or err["type"] == "extra_forbidden"
        named = err["loc"][-1] if err["type"] in ("missing", "extra_forbidden") else None
        if (path, is_key, named) in seen:
            continue
        seen.add((path, is_key, named))
        message = _message(model, path, err)
        meant = swaps.get(path[:-1]) if err["type"] == "extra_forbidden" else None
        if meant is not None and "did you mean" not in message:
            message = f"unknown key '{path[-1]}'; did you mean '{meant}'?"
        out.append(doc.finding(path, "E200", message, key=is_key))
    return out


def _swaps(doc: Document, errors: list[ErrorDetails]) -> dict[Path_, str]:
    """The mappings with one unknown key and one missing key: the unknown one stands for it (`dp:`
    for `do:`), however far apart they are spelt."""
    unknown: dict[Path_, set[object]] = {}
    missing: dict[Path_, set[str]] = {}
    for err in errors:
        if err["type"] == "extra_forbidden":
            unknown.setdefault(data_path(doc.data, err["loc"][:-1])[0], set()).add(err["loc"][-1])
        elif err["type"] == "missing":
            missing.setdefault(data_path(doc.data, err["loc"])[0], set()).add(str(err["loc"][-1]))
    return {
        path: next(iter(keys))
        for path, keys in missing.items()
        if len(keys) == 1 and len(unknown.get(path, ())) == 1
    }


def _misspelt(model: type[BaseModel], doc: Document, errors: list[ErrorDetails]) -> set[Path_]:
    """The mappings holding an unknown key that is close to a key they may have."""
    found: set[Path_] = set()
    for err in errors:
        if err["type"] == "extra_forbidden" and did_you_mean(
            str(err["loc"][-1]), _keys_near(model, err["loc"])
        ):
            found.add(data_path(doc.data, err["loc"][:-1])[0])
    return found


def _keys_near(model: type[BaseModel], loc: tuple[int | str, ...]) -> list[str]:
    """The keys allowed where `loc` ends, and in a tagged union, those of its other alternatives."""
    keys = _allowed_keys(model, loc[:-1])
    if len(loc) >= 2 and _is_tag(loc[-2]):
        union = _strip(_walk(model, loc[:-2]))
        for arg in get_args(union):
            tags = [m for m in getattr(arg, "__metadata__", ()) if isinstance(m, Tag)]
            if tags:
                keys += _allowed_keys(model, (*loc[:-2], tags[0].tag))
    return sorted(set(keys))


def _walk(model: type[BaseModel], loc: tuple[int | str, ...]) -> Any:
    current: Any = model
    for part in loc:
        current = _step(current, part)
    return current


def _is_tag(part: int | str) -> bool:
    return isinstance(part, str) and "-" in part


def data_path(data: Any, loc: tuple[int | str, ...]) -> tuple[Path_, bool]:
    """Follow pydantic's loc through the data, skipping the union tags that name no data."""
    path: list[str | int] = []
    for part in loc:
        if part == "[key]":
            return tuple(path), True
        found, child = _child(data, part)
        if found:
            data = child
            path.append(part)
        elif not _is_tag(part):
            break  # pydantic names something the data lacks (a missing key): stop at its parent
    return tuple(path), False


def _child(data: Any, part: int | str) -> tuple[bool, Any]:
    if isinstance(data, dict):
        return part in data, data.get(part)
    if isinstance(data, list) and isinstance(part, int) and 0 <= part < len(data):
        return True, data[part]
    return False, None


def _message(model: type[BaseModel], path: Path_, err: ErrorDetails) -> str:
    kind, value = err["type"], err.get("input")
    last = path[-1] if path else None
    where = f"'{last}'" if isinstance(last, str) else "this value"
    if kind == "extra_forbidden":
        allowed = _allowed_keys(model, err["loc"][:-1])
        if last in _CALL_ONLY and "parallel-state" in err["loc"]:
            return (f"a parallel state has no {where}: its regions call behaviours "
                    "(docs/REFERENCE.md#parallel-states)")
        hint = did_you_mean(str(last), [k for k in _keys_near(model, err["loc"]) if k != str(last)])
        return f"unknown key {where}" + (hint or f" (allowed: {', '.join(allowed)})")
    if kind == "missing":
        return f"missing required key '{err['loc'][-1]}'"
    if last in _COUNTS:
        return f"'{last}' must be {_COUNTS[last]} or a '${{…}}' expression, not {_describe(value)}" + _wrap(
            value
        )
    if kind in _BOUNDS or kind in ("finite_number", "too_long", "value_error", "refused"):
        return _refused(model, path, where, err)
    if kind == "too_short":
        least = (err.get("ctx") or {}).get("min_length", 1)
        return f"{where} must have at least {least} {'entry' if least == 1 else 'entries'}, not none"
    if kind == "string_pattern_mismatch":
        return f"bad name {_describe(value)}: names match {NAME_PATTERN}"
    if kind in _TYPE_NAMES:
        return f"{where} must be {_TYPE_NAMES[kind]}, not {_describe(value)}"
    if kind == "literal_error":
        expected = [
            str(v)
            for v in (err.get("ctx") or {})
            .get("expected", "")
            .replace("'", "")
            .replace(" or ", ", ")
            .split(", ")
        ]
        return f"{where}: {err['msg'].lower()}, not {_describe(value)}" + did_you_mean(str(value), expected)
    return f"{where}: {err['msg']}"


def _refused(model: type[BaseModel], path: Path_, where: str, err: ErrorDetails) -> str:
    """A value out of its range (every bound of its field, the value, the field's description), or
    refused by a validator (its message, which names the value when it is a `refused` error)."""
    kind, value = err["type"], err.get("input")
    if kind in _BOUNDS:
        field = _field(model, err["loc"])
        note = f" ({field.description})" if field is not None and field.description else ""
        return f"{where} must be {_range(field, err)}, not {_describe(value)}{note}"
    if kind == "finite_number":
        return f"{where} must be a finite number, not {_describe(value)}"
    if kind == "too_long":
        most = (err.get("ctx") or {}).get("max_length")
        return f"{where} must have at most {most} entries, not {len(value)}"
    message = err["msg"].removeprefix("Value error, ")
    return message if kind == "refused" or not path else f"{where}: {message}"


_BOUNDS = {"greater_than": "gt", "greater_than_equal": "ge", "less_than": "lt", "less_than_equal": "le"}
_SIGNS = {"gt": ">", "ge": ">=", "lt": "<", "le": "<="}


def _range(field: FieldInfo | None, err: ErrorDetails) -> str:
    """`> 0 and <= 3`: every bound of the field (the error's own when the field is not found)."""
    bounds: dict[str, Any] = {}
    for item in field.metadata if field is not None else ():
        for name in _SIGNS:
            if getattr(item, name, None) is not None:
                bounds[name] = getattr(item, name)
    if not bounds:
        bounds = {_BOUNDS[err["type"]]: (err.get("ctx") or {}).get(_BOUNDS[err["type"]])}
    return " and ".join(f"{_SIGNS[name]} {_number(bound)}" for name, bound in bounds.items())


def _number(value: Any) -> str:
    return f"{value:g}" if isinstance(value, float) else str(value)


def _field(model: type[BaseModel], loc: tuple[int | str, ...]) -> FieldInfo | None:
    """The field an error's location ends at, when it is a model's."""
    current: Any = model
    for part in loc[:-1]:
        current = _step(current, part)
    current = _only_model(_strip(current)) or _strip(current)
    if isinstance(current, type) and issubclass(current, BaseModel):
        for name, field in current.model_fields.items():
            if loc[-1] in (name, field.alias):
                return field
    return None


_CALL_ONLY = ("do", "with", "save", "retry", "choose")
_COUNTS = {
    "timer": "a number of seconds > 0",
    "times": "a whole number > 0",
    "delay": "a number of seconds >= 0",
}


def _wrap(value: Any) -> str:
    """The forgotten `${…}` (issue 13): say how to wrap text that reads as an expression."""
    text = value.strip() if isinstance(value, str) else ""
    return f"; write '${{{text}}}'" if "${" not in text and reads(text) else ""


def _describe(value: Any) -> str:
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        lines = value.splitlines()
        return f"'{value}'" if len(lines) <= 1 else f"'{lines[0]}…' (text of {len(lines)} lines)"
    if isinstance(value, dict):
        return "a mapping"
    if isinstance(value, list):
        return "a list"
    return shown(value)


def _allowed_keys(model: type[BaseModel], loc: tuple[int | str, ...]) -> list[str]:
    """The keys of the model that an error's location points into."""
    current: Any = model
    for part in loc:
        current = _step(current, part)
    current = _only_model(_strip(current)) or _strip(current)
    if isinstance(current, type) and issubclass(current, BaseModel):
        return sorted(f.alias or n for n, f in current.model_fields.items())
    return []


def _strip(annotation: Any) -> Any:
    while get_origin(annotation) is Annotated:
        annotation = get_args(annotation)[0]
    return annotation


def _step(annotation: Any, part: int | str) -> Any:
    annotation = _strip(annotation)
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        for name, field in annotation.model_fields.items():
            if part in (name, field.alias):
                return field.annotation
        return annotation
    origin = get_origin(annotation)
    if origin in (dict, list):
        return get_args(annotation)[-1]
    if origin in (Union, types.UnionType):
        for arg in get_args(annotation):
            tags = [m for m in getattr(arg, "__metadata__", ()) if isinstance(m, Tag)]
            if tags and tags[0].tag == part:
                return arg
        model = _only_model(annotation)
        if model is not None:  # `retry: Retry | None`: the keys are the model's
            return _step(model, part)
        present = [a for a in get_args(annotation) if a is not type(None)]
        if len(present) == 1:  # `tables: list[TableSpec] | None`: step into the list
            return _step(present[0], part)
    return annotation


def _only_model(annotation: Any) -> type[BaseModel] | None:
    if get_origin(annotation) not in (Union, types.UnionType):
        return None
    models = [
        a for a in map(_strip, get_args(annotation)) if isinstance(a, type) and issubclass(a, BaseModel)
    ]
    return models[0] if len(models) == 1 else None
