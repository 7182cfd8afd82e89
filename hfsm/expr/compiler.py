"""Expressions parsed with `ast`, checked against a whitelist, compiled to closures. Nothing
reaches `eval`. Names are checked when the file is loaded; values when the expression runs."""

from __future__ import annotations

import ast
import difflib
from collections.abc import Callable
from typing import Any

from hfsm import bounds
from hfsm.expr.funcs import FUNCS, is_number, kind
from hfsm.expr.ops import BIN, CMP, LITERAL_NAMES, all_of, any_of, arith, bounded
from hfsm.expr.scope import IN, ROOTS, ExprSyntaxError, ExprValueError, Fn, Names, Scope
from hfsm.expr.source import Source
from hfsm.expr.text import short
from hfsm.names import did_you_mean


class _Compiler:
    def __init__(self, names: Names, where: Callable[[ast.AST], tuple[int, int]]) -> None:
        self.names = names
        self.where = where  # a node's offsets in the source given to compile_expr

    def at(self, message: str, node: ast.AST) -> ExprSyntaxError:
        return ExprSyntaxError(message, *self.where(node))

    def compile(self, node: ast.AST) -> Fn:
        method = getattr(self, f"c_{type(node).__name__}", None)
        if method is None:
            raise self.at(f"'{_snippet(node)}' is not allowed in an expression", node)
        try:
            fn: Fn = method(node)
        except ExprSyntaxError as exc:
            if exc.start is None:
                raise self.at(exc.message, node) from None
            raise
        return fn

    def c_Constant(self, node: ast.Constant) -> Fn:
        value = node.value
        if not isinstance(value, int | float | str | bool | type(None)):
            raise ExprSyntaxError(f"literal {short(repr(value))} is not allowed")
        try:
            bounds.check_scalar(value)
        except bounds.LimitError as exc:
            raise ExprSyntaxError(f"literal {_snippet(node)}: {exc}") from None
        return lambda s: value

    def c_Name(self, node: ast.Name) -> Fn:
        if node.id in LITERAL_NAMES:
            value = LITERAL_NAMES[node.id]
            return lambda s: value
        if node.id in ROOTS:
            shown = "in" if node.id == IN else node.id
            raise ExprSyntaxError(f"'{shown}' alone is not a value; write {shown}.NAME")
        raise ExprSyntaxError(f"unknown name '{short(node.id)}'{self.names.hint(node.id)}")

    def c_Attribute(self, node: ast.Attribute) -> Fn:
        if not isinstance(node.value, ast.Name) or node.value.id not in ROOTS:
            inner = _snippet(node.value)
            hint = ""
            if isinstance(node.value, ast.Attribute | ast.Subscript):
                hint = f"; a dict's entry is read with brackets: {inner}['{short(node.attr)}']"
            elif isinstance(node.value, ast.Name):
                shown = ["in" if root == IN else root for root in ROOTS]
                close = difflib.get_close_matches(node.value.id, shown, n=1, cutoff=0.6)
                hint = f"; did you mean '{close[0]}.{short(node.attr)}'?" if close else ""
            raise ExprSyntaxError(
                f"'{_snippet(node)}': no attribute access but params.X, vars.X, in.X, agent.id, "
                f"state.time, state.attempt, machine.time, scope.name and scope.agents{hint}"
            )
        root, attr = node.value.id, node.attr
        self.names.check(root, attr)
        if root == "agent":
            return lambda s: s.agent
        if root == "params":
            return lambda s: s.params[attr]
        if root == "vars":
            return lambda s: s.vars[attr]
        if root == IN:
            return lambda s: s.live.input(attr)
        if root == "machine":
            return lambda s: s.live.machine_time()
        if root == "scope":
            return (lambda s: s.live.scope_name()) if attr == "name" else (lambda s: s.live.scope_agents())
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
                message = f"cannot take [{short(repr(key))}] of {kind(container)}: {short(str(exc))}"
                raise ExprValueError(message) from None

        return subscript

    def c_BinOp(self, node: ast.BinOp) -> Fn:
        op = type(node.op)
        if op not in BIN:
            raise ExprSyntaxError(f"operator in '{_snippet(node)}' is not allowed")
        fn, left, right = arith(op, BIN[op]), self.compile(node.left), self.compile(node.right)

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
            if not is_number(value):
                raise ExprValueError(f"cannot negate {kind(value)}")
            return sign * value

        return unary

    def c_BoolOp(self, node: ast.BoolOp) -> Fn:
        parts = [self.compile(v) for v in node.values]
        if isinstance(node.op, ast.And):
            return lambda s: all_of(parts, s)
        return lambda s: any_of(parts, s)

    def c_Compare(self, node: ast.Compare) -> Fn:
        ops = [type(o) for o in node.ops]
        if any(o not in CMP for o in ops):
            raise ExprSyntaxError(f"comparison in '{_snippet(node)}' is not allowed")
        terms = [self.compile(node.left), *(self.compile(c) for c in node.comparators)]
        fns = [CMP[o] for o in ops]

        def compare(s: Scope) -> bool:
            left = terms[0](s)
            for fn, term in zip(fns, terms[1:], strict=True):
                right = term(s)
                try:
                    if not fn(left, right):
                        return False
                except TypeError:
                    raise ExprValueError(f"cannot compare {kind(left)} and {kind(right)}") from None
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
        if not isinstance(node.func, ast.Name):
            raise self.at(f"'{_snippet(node.func)}' cannot be called: only functions by name", node.func)
        name = node.func.id
        func = FUNCS.get(name)
        if func is None:
            raise self.at(f"unknown function '{short(name)}'{did_you_mean(name, FUNCS)}", node.func)
        if node.keywords or any(isinstance(a, ast.Starred) for a in node.args):
            raise ExprSyntaxError(f"'{name}()' takes plain arguments only")
        if len(node.args) < func.least or (func.most is not None and len(node.args) > func.most):
            raise ExprSyntaxError(f"{name}() takes {func.arity()}, not {len(node.args)}")
        fn, args = func.fn, [self.compile(a) for a in node.args]

        def call(s: Scope) -> Any:
            try:
                return fn(*(a(s) for a in args))
            except (TypeError, ValueError, OverflowError) as exc:
                raise ExprValueError(f"{name}(): {exc}") from None

        return call


def _snippet(node: ast.AST) -> str:
    return short(ast.unparse(node).replace(f"{IN}.", "in."))


def compile_expr(source: str, names: Names) -> Fn:
    """Compile a bare expression; raise ExprSyntaxError with a readable message and the offsets in
    `source` of the characters at fault."""
    text = Source.of(source)
    try:
        tree = text.parse()
    except ExprSyntaxError as exc:
        bare = source.strip()
        hint = f"; a condition is a bare expression: write '{bare[2:-1]}'" if bare.startswith("${") else ""
        message = f"bad expression '{short(bare)}': {exc.message}{hint}"
        raise ExprSyntaxError(message, exc.start, exc.end) from None
    return _Compiler(names, text.where).compile(tree)


def reads(source: str) -> set[str]:
    """The dotted names an expression reads (`vars.n`, `state.time`, `in.x`); empty if it does not parse."""
    return {name for name, _, _ in reads_at(source)}


def reads_at(source: str) -> list[tuple[str, int, int]]:
    """The dotted names an expression reads, each with its offsets in `source`, in the order
    they stand; empty if it does not parse."""
    try:
        text = Source.of(source)
        tree = text.parse()
    except ExprSyntaxError:
        return []
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id in ROOTS:
            root = "in" if node.value.id == IN else node.value.id
            found.append((f"{root}.{node.attr}", *text.where(node)))
    return sorted(found, key=lambda item: item[1])


TIMED = frozenset({"state.time", "machine.time"})
