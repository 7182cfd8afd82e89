"""Expressions (SPEC section 7): parsed with `ast`, checked against a whitelist, compiled to closures.

Nothing reaches `eval`. Names are checked when the file is loaded; values when the expression runs.
"""

from __future__ import annotations

import ast
import io
import math
import operator
import tokenize
from collections.abc import Callable, Collection, Mapping
from dataclasses import dataclass
from typing import Any, Protocol

from hfsm import bounds
from hfsm.names import did_you_mean


class ExprSyntaxError(Exception):
    """An expression that cannot be accepted at load time."""


class ExprValueError(Exception):
    """An expression that failed while running: becomes the event `error`."""


class Live(Protocol):
    """What changes while a state runs (SPEC 12, 13): read only when an expression asks."""

    def state_time(self) -> float: ...

    def state_attempt(self) -> int: ...

    def machine_time(self) -> float: ...

    def input(self, name: str) -> Any: ...


class _Nowhere:
    """The live values of a scope outside any running state: reading one is a run-time error."""

    def state_time(self) -> float:
        raise ExprValueError("'state.time' cannot be read here")

    def state_attempt(self) -> int:
        raise ExprValueError("'state.attempt' cannot be read here")

    def machine_time(self) -> float:
        raise ExprValueError("'machine.time' cannot be read here")

    def input(self, name: str) -> Any:
        raise ExprValueError(f"'in.{name}' cannot be read here")


NOWHERE: Live = _Nowhere()


@dataclass(slots=True)
class Scope:
    params: Mapping[str, Any]
    vars: Mapping[str, Any]
    agent: str
    live: Live = NOWHERE


Fn = Callable[[Scope], Any]

_IN = "__in__"  # what `in.x` reads as once tokenized: `in` is a Python keyword
_ROOTS = ("params", "vars", "agent", "state", "machine", _IN)
_LIVE = {"state": ("time", "attempt"), "machine": ("time",)}


@dataclass(frozen=True)
class Names:
    """What an expression may refer to at the place it stands.

    `state`: whether `state.time`/`state.attempt` may be read; `machine_time`: `machine.time`;
    `inputs`: the inputs the run's world declares, or None to accept any `in.x` (checked elsewhere).
    """

    params: Collection[str]
    vars: Collection[str] | None  # None: `vars` may not be read here
    state: bool = True
    machine_time: bool = True
    inputs: Collection[str] | None = None

    def check(self, root: str, attr: str) -> None:
        if root == "agent":
            if attr != "id":
                raise ExprSyntaxError(f"unknown name 'agent.{attr}'; only 'agent.id' exists")
            return
        if root in _LIVE:
            self._check_live(root, attr)
            return
        if root == _IN:
            if self.inputs is not None and attr not in self.inputs:
                declared = ", ".join(sorted(self.inputs)) or "none"
                hint = did_you_mean(attr, self.inputs)
                raise ExprSyntaxError(f"unknown input 'in.{attr}' (the world declares {declared}){hint}")
            return
        pool = self.params if root == "params" else self.vars
        if pool is None:
            raise ExprSyntaxError(f"'{root}.{attr}': only params and agent.id may be read here")
        if attr not in pool:
            kind = "param" if root == "params" else "variable"
            raise ExprSyntaxError(f"unknown {kind} '{attr}'{did_you_mean(attr, pool)}")

    def _check_live(self, root: str, attr: str) -> None:
        known = _LIVE[root]
        if attr not in known:
            close = did_you_mean(attr, known)
            full = [f"'{root}.{k}'" for k in known]
            hint = close.replace("'", f"'{root}.", 1) if close else f"; only {' and '.join(full)}"
            raise ExprSyntaxError(f"unknown name '{root}.{attr}'{hint}")
        if root == "state" and not self.state:
            raise ExprSyntaxError(
                f"'state.{attr}' cannot be read here; only in a state's with, timer and watch, "
                "the machine's watch, and a choice's if"
            )
        if root == "machine" and not self.machine_time:
            raise ExprSyntaxError("'machine.time' cannot be read in the machine's own timer")


_BIN: dict[type, Callable[[Any, Any], Any]] = {
    ast.Add: operator.add,
    ast.Sub: operator.sub,
    ast.Mult: operator.mul,
    ast.Div: operator.truediv,
    ast.FloorDiv: operator.floordiv,
    ast.Mod: operator.mod,
}
_CMP: dict[type, Callable[[Any, Any], Any]] = {
    ast.Eq: operator.eq,
    ast.NotEq: operator.ne,
    ast.Lt: operator.lt,
    ast.LtE: operator.le,
    ast.Gt: operator.gt,
    ast.GtE: operator.ge,
    ast.In: lambda a, b: operator.contains(b, a),
    ast.NotIn: lambda a, b: not operator.contains(b, a),
}
_LITERAL_NAMES = {"true": True, "false": False, "null": None}


def _number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


_SYMBOLS: dict[type, str] = {ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/", ast.FloorDiv: "//"}


def _arith(op: type, fn: Callable[[Any, Any], Any]) -> Callable[[Any, Any], Any]:
    def apply(a: Any, b: Any) -> Any:
        both_numbers = _number(a) and _number(b)
        joinable = op is ast.Add and type(a) is type(b) and isinstance(a, str | list)
        if not (both_numbers or joinable):
            raise ExprValueError(f"cannot apply '{_SYMBOLS.get(op, '%')}' to {_kind(a)} and {_kind(b)}")
        return _bounded(op, fn, a, b)

    return apply


def _bounded(op: type, fn: Callable[[Any, Any], Any], a: Any, b: Any) -> Any:
    """Apply `fn`; refuse a result past the limits of hfsm.bounds, a big product before it is made."""
    try:
        if op is ast.Mult and a.__class__ is int and b.__class__ is int:
            bounds.product_fits(a, b)
        elif op is ast.Add and not _number(a):
            bounds.joined_fits(a, b)
            return bounds.check_value(fn(a, b))
        result = fn(a, b)
        if result.__class__ is float:
            return bounds.check_float(result)
        return bounds.check_int(result)
    except bounds.LimitError as exc:
        raise ExprValueError(str(exc)) from None
    except OverflowError:
        raise ExprValueError("the result is too large for a number") from None


def _kind(value: Any) -> str:
    return {bool: "bool", int: "int", float: "float", str: "str", list: "list", dict: "dict"}.get(
        type(value), "null" if value is None else type(value).__name__
    )


def _len(value: Any) -> int:
    if not isinstance(value, str | list | dict):
        raise ExprValueError(f"len() of {_kind(value)}")
    return len(value)


def _round(value: Any, digits: Any = None) -> Any:
    if not _number(value) or (digits is not None and not isinstance(digits, int)):
        raise ExprValueError("round() takes a number and an optional whole number of digits")
    return round(value) if digits is None else round(value, digits)


def _abs(value: Any) -> Any:
    if not _number(value):
        raise ExprValueError(f"abs() of {_kind(value)}")
    return abs(value)


_FUNCS: dict[str, Callable[..., Any]] = {"abs": _abs, "min": min, "max": max, "round": _round, "len": _len}


class _Compiler:
    def __init__(self, names: Names) -> None:
        self.names = names

    def compile(self, node: ast.AST) -> Fn:
        method = getattr(self, f"c_{type(node).__name__}", None)
        if method is None:
            raise ExprSyntaxError(f"'{_snippet(node)}' is not allowed in an expression")
        fn: Fn = method(node)
        return fn

    def c_Constant(self, node: ast.Constant) -> Fn:
        value = node.value
        if not isinstance(value, int | float | str | bool | type(None)):
            raise ExprSyntaxError(f"literal {value!r} is not allowed")
        try:
            bounds.check_scalar(value)
        except bounds.LimitError as exc:
            raise ExprSyntaxError(f"literal {_snippet(node)[:40]}: {exc}") from None
        return lambda s: value

    def c_Name(self, node: ast.Name) -> Fn:
        if node.id in _LITERAL_NAMES:
            value = _LITERAL_NAMES[node.id]
            return lambda s: value
        if node.id in _ROOTS:
            shown = "in" if node.id == _IN else node.id
            raise ExprSyntaxError(f"'{shown}' alone is not a value; write {shown}.NAME")
        hint = did_you_mean(node.id, ["true", "false", "null", "params", "vars", "agent", "state", "machine"])
        raise ExprSyntaxError(f"unknown name '{node.id}'{hint}")

    def c_Attribute(self, node: ast.Attribute) -> Fn:
        if not isinstance(node.value, ast.Name) or node.value.id not in _ROOTS:
            raise ExprSyntaxError(
                f"'{_snippet(node)}': only params.X, vars.X, in.X, agent.id, state.time, state.attempt "
                "and machine.time"
            )
        root, attr = node.value.id, node.attr
        self.names.check(root, attr)
        if root == "agent":
            return lambda s: s.agent
        if root == "params":
            return lambda s: s.params[attr]
        if root == "vars":
            return lambda s: s.vars[attr]
        if root == _IN:
            return lambda s: s.live.input(attr)
        if root == "machine":
            return lambda s: s.live.machine_time()
        if attr == "time":
            return lambda s: s.live.state_time()
        return lambda s: s.live.state_attempt()

    def c_Subscript(self, node: ast.Subscript) -> Fn:
        value, index = self.compile(node.value), self.compile(node.slice)

        def subscript(s: Scope) -> Any:
            container, key = value(s), index(s)
            try:
                return container[key]
            except (KeyError, IndexError, TypeError) as exc:
                raise ExprValueError(f"cannot take [{key!r}] of {_kind(container)}: {exc}") from None

        return subscript

    def c_BinOp(self, node: ast.BinOp) -> Fn:
        op = type(node.op)
        if op not in _BIN:
            raise ExprSyntaxError(f"operator in '{_snippet(node)}' is not allowed")
        fn, left, right = _arith(op, _BIN[op]), self.compile(node.left), self.compile(node.right)

        def binop(s: Scope) -> Any:
            try:
                return fn(left(s), right(s))
            except ZeroDivisionError:
                raise ExprValueError(f"division by zero in '{_snippet(node)}'") from None

        return binop

    def c_UnaryOp(self, node: ast.UnaryOp) -> Fn:
        operand = self.compile(node.operand)
        if isinstance(node.op, ast.Not):
            return lambda s: not operand(s)
        if not isinstance(node.op, ast.USub | ast.UAdd):
            raise ExprSyntaxError(f"operator in '{_snippet(node)}' is not allowed")
        sign = -1 if isinstance(node.op, ast.USub) else 1

        def unary(s: Scope) -> Any:
            value = operand(s)
            if not _number(value):
                raise ExprValueError(f"cannot negate {_kind(value)}")
            return sign * value

        return unary

    def c_BoolOp(self, node: ast.BoolOp) -> Fn:
        parts = [self.compile(v) for v in node.values]
        if isinstance(node.op, ast.And):
            return lambda s: _all(parts, s)
        return lambda s: _any(parts, s)

    def c_Compare(self, node: ast.Compare) -> Fn:
        ops = [type(o) for o in node.ops]
        if any(o not in _CMP for o in ops):
            raise ExprSyntaxError(f"comparison in '{_snippet(node)}' is not allowed")
        terms = [self.compile(node.left), *(self.compile(c) for c in node.comparators)]
        fns = [_CMP[o] for o in ops]

        def compare(s: Scope) -> bool:
            left = terms[0](s)
            for fn, term in zip(fns, terms[1:], strict=True):
                right = term(s)
                try:
                    if not fn(left, right):
                        return False
                except TypeError:
                    raise ExprValueError(f"cannot compare {_kind(left)} and {_kind(right)}") from None
                left = right
            return True

        return compare

    def c_IfExp(self, node: ast.IfExp) -> Fn:
        test, body, orelse = self.compile(node.test), self.compile(node.body), self.compile(node.orelse)
        return lambda s: body(s) if test(s) else orelse(s)

    def c_List(self, node: ast.List) -> Fn:
        items = [self.compile(e) for e in node.elts]
        return lambda s: bounded([i(s) for i in items])

    def c_Dict(self, node: ast.Dict) -> Fn:
        if any(k is None for k in node.keys):
            raise ExprSyntaxError("'**' is not allowed in an expression")
        pairs = [(self.compile(k), self.compile(v)) for k, v in zip(node.keys, node.values, strict=True) if k]
        return lambda s: bounded({k(s): v(s) for k, v in pairs})

    def c_Call(self, node: ast.Call) -> Fn:
        if not isinstance(node.func, ast.Name) or node.func.id not in _FUNCS:
            name = node.func.id if isinstance(node.func, ast.Name) else _snippet(node.func)
            raise ExprSyntaxError(f"unknown function '{name}'{did_you_mean(name, _FUNCS)}")
        if node.keywords or any(isinstance(a, ast.Starred) for a in node.args):
            raise ExprSyntaxError(f"'{node.func.id}()' takes plain arguments only")
        fn, args = _FUNCS[node.func.id], [self.compile(a) for a in node.args]

        def call(s: Scope) -> Any:
            try:
                return fn(*(a(s) for a in args))
            except (TypeError, ValueError) as exc:
                raise ExprValueError(f"{node.func.id}(): {exc}") from None  # type: ignore[attr-defined]

        return call


def bounded(value: Any) -> Any:
    """A built list, dict or string, checked against the limits of hfsm.bounds."""
    try:
        return bounds.check_value(value)
    except bounds.LimitError as exc:
        raise ExprValueError(str(exc)) from None


def _all(parts: list[Fn], s: Scope) -> Any:
    value: Any = True
    for part in parts:
        value = part(s)
        if not value:
            return value
    return value


def _any(parts: list[Fn], s: Scope) -> Any:
    value: Any = False
    for part in parts:
        value = part(s)
        if value:
            return value
    return value


def _snippet(node: ast.AST) -> str:
    return ast.unparse(node).replace(f"{_IN}.", "in.")


_OPERANDS = (tokenize.NUMBER, tokenize.STRING)


def _inputs_renamed(source: str) -> str:
    """`in.x` as `__in__.x`, where `in` stands as an operand (not the operator `a in b`)."""
    if "in" not in source:
        return source
    try:
        tokens = [t for t in tokenize.generate_tokens(io.StringIO(source).readline) if t.type != tokenize.NL]
    except (tokenize.TokenError, SyntaxError, IndentationError):
        return source  # ast.parse reports it
    lines = source.splitlines(keepends=True)
    starts = [0]
    for line in lines:
        starts.append(starts[-1] + len(line))
    cuts = []
    for i, tok in enumerate(tokens):
        if tok.type == tokenize.NAME and tok.string == _IN:
            raise ExprSyntaxError(f"unknown name '{_IN}'")
        if tok.string != "in" or i + 1 >= len(tokens) or tokens[i + 1].string != ".":
            continue
        before = tokens[i - 1] if i else None
        operand_before = before is not None and (
            before.type in _OPERANDS
            or before.string in (")", "]", "}")
            or (before.type == tokenize.NAME and before.string not in _KEYWORDS)
        )
        if not operand_before:
            cuts.append(starts[tok.start[0] - 1] + tok.start[1])
    for at in reversed(cuts):
        source = source[:at] + _IN + source[at + 2 :]
    return source


_KEYWORDS = {"and", "or", "not", "in", "if", "else", "is", "lambda"}


def compile_expr(source: str, names: Names) -> Fn:
    """Compile a bare expression; raise ExprSyntaxError with a readable message."""
    text = _inputs_renamed(source.strip())
    try:
        tree = ast.parse(text, mode="eval")
    except SyntaxError as exc:
        bare = source.strip()
        hint = f"; a condition is a bare expression: write '{bare[2:-1]}'" if bare.startswith("${") else ""
        raise ExprSyntaxError(f"bad expression '{source}': {exc.msg}{hint}") from None
    return _Compiler(names).compile(tree.body)


def reads(source: str) -> set[str]:
    """The dotted names an expression reads (`vars.n`, `state.time`, `in.x`); empty if it does not parse."""
    try:
        tree = ast.parse(_inputs_renamed(source.strip()), mode="eval")
    except (SyntaxError, ExprSyntaxError):
        return set()
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id in _ROOTS:
            root = "in" if node.value.id == _IN else node.value.id
            found.add(f"{root}.{node.attr}")
    return found


TIMED = frozenset({"state.time", "machine.time"})


def format_number(value: float) -> str:
    if math.isfinite(value) and value == int(value) and "e" not in repr(value):
        return str(int(value))
    return repr(value)


def to_text(value: Any) -> str:
    """A value as text: strings as they are, numbers in their fewest digits, lists and dicts as JSON."""
    if isinstance(value, str):
        return value
    return _json(value)


def _json(value: Any) -> str:
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return format_number(value)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, str):
        import json

        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, list):
        return "[" + ", ".join(_json(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{_json(str(k))}: {_json(v)}" for k, v in value.items()) + "}"
    return _json(str(value))
