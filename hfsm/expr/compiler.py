"""Expressions parsed with `ast`, checked against a whitelist, compiled to closures. Nothing
reaches `eval`. Names are checked when the file is loaded; values when the expression runs."""

from __future__ import annotations

import ast
import io
import tokenize
from typing import Any

from hfsm import bounds
from hfsm.expr.ops import BIN, CMP, FUNCS, LITERAL_NAMES, all_of, any_of, arith, bounded, is_number, kind
from hfsm.expr.scope import IN, ROOTS, ExprSyntaxError, ExprValueError, Fn, Names, Scope
from hfsm.names import did_you_mean


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
        if node.id in LITERAL_NAMES:
            value = LITERAL_NAMES[node.id]
            return lambda s: value
        if node.id in ROOTS:
            shown = "in" if node.id == IN else node.id
            raise ExprSyntaxError(f"'{shown}' alone is not a value; write {shown}.NAME")
        roots = ["true", "false", "null", "params", "vars", "agent", "state", "machine", "scope"]
        hint = did_you_mean(node.id, roots)
        raise ExprSyntaxError(f"unknown name '{node.id}'{hint}")

    def c_Attribute(self, node: ast.Attribute) -> Fn:
        if not isinstance(node.value, ast.Name) or node.value.id not in ROOTS:
            raise ExprSyntaxError(
                f"'{_snippet(node)}': only params.X, vars.X, in.X, agent.id, state.time, state.attempt, "
                "machine.time, scope.name and scope.agents"
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
                raise ExprValueError(f"cannot take [{key!r}] of {kind(container)}: {exc}") from None

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
        if not isinstance(node.func, ast.Name) or node.func.id not in FUNCS:
            name = node.func.id if isinstance(node.func, ast.Name) else _snippet(node.func)
            raise ExprSyntaxError(f"unknown function '{name}'{did_you_mean(name, FUNCS)}")
        if node.keywords or any(isinstance(a, ast.Starred) for a in node.args):
            raise ExprSyntaxError(f"'{node.func.id}()' takes plain arguments only")
        fn, args = FUNCS[node.func.id], [self.compile(a) for a in node.args]

        def call(s: Scope) -> Any:
            try:
                return fn(*(a(s) for a in args))
            except (TypeError, ValueError) as exc:
                raise ExprValueError(f"{node.func.id}(): {exc}") from None  # type: ignore[attr-defined]

        return call


def _snippet(node: ast.AST) -> str:
    return ast.unparse(node).replace(f"{IN}.", "in.")


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
        if tok.type == tokenize.NAME and tok.string == IN:
            raise ExprSyntaxError(f"unknown name '{IN}'")
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
        source = source[:at] + IN + source[at + 2 :]
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
        if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id in ROOTS:
            root = "in" if node.value.id == IN else node.value.id
            found.add(f"{root}.{node.attr}")
    return found


TIMED = frozenset({"state.time", "machine.time"})
