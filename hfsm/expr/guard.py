"""Parse an expression whatever its size: bounded by a cheap scan before Python's parser sees it.

Python's parser fails on deep input with MemoryError or RecursionError (10,000 unary minus signs,
a sum of 20,000 terms) and on long integer literals with ValueError. The scan below bounds the
length, the bracket nesting, the operators and the digits of a literal first; the tree is then
measured without recursion, so that compiling and evaluating it stays far from Python's limits.
Every refusal is an ExprSyntaxError with the offsets of the characters at fault.
"""

from __future__ import annotations

import ast
import re

from hfsm import bounds
from hfsm.expr.scope import ExprSyntaxError

MAX_CHARS = 10_000  # characters of one expression
MAX_NESTING = 100  # brackets ( [ { nested
MAX_OPERATORS = 1_000  # operators, keyword operators, dots and brackets in one expression
MAX_DEPTH = 100  # operations nested in the parsed expression
MAX_DIGITS = bounds.MAX_DIGITS  # digits of a number literal

_KEYWORD_OPERATORS = frozenset({"not", "and", "or", "if", "else", "in", "is", "lambda"})


def scan(text: str) -> None:
    """Refuse text past the limits of this module, at the first character past one."""
    if len(text) <= MAX_NESTING:
        return  # too short to pass any limit
    if len(text) > MAX_CHARS:
        raise ExprSyntaxError(
            f"an expression of {len(text):,} characters: the limit is {MAX_CHARS:,}", 0, len(text)
        )
    depth = operators = 0
    for token in _TOKENS.finditer(text):
        kind, start, end = token.lastgroup, token.start(), token.end()
        if kind == "number":
            digits = sum(map(str.isdigit, token.group()))
            if digits > MAX_DIGITS:
                message = f"a number literal of {digits:,} digits: the limit is {MAX_DIGITS:,}"
                raise ExprSyntaxError(message, start, end)
            continue
        if kind == "string" or (kind == "name" and token.group() not in _KEYWORD_OPERATORS):
            continue
        if kind == "close":
            depth = max(0, depth - 1)
            continue
        operators += 1
        if operators > MAX_OPERATORS:
            message = f"more than {MAX_OPERATORS:,} operators in one expression (the limit)"
            raise ExprSyntaxError(message, start, end)
        if kind == "open":
            depth += 1
            if depth > MAX_NESTING:
                raise ExprSyntaxError(f"brackets nested more than {MAX_NESTING} deep (the limit)", start, end)


_TOKENS = re.compile(
    "|".join(
        [
            r"""(?P<string>'{3}(?s:.*?)(?:'{3}|\Z)|"{3}(?s:.*?)(?:"{3}|\Z)|'(?:[^'\\\n]|\\.)*'?|"(?:[^"\\\n]|\\.)*"?)""",
            r"(?P<number>\d[\w.]*?(?:[eE][+-]\d[\w.]*)?(?![\w.])|\d[\w.]*|\.\d[\w.]*)",
            r"(?P<name>[^\W\d]\w*)",
            r"(?P<open>[(\[{])",
            r"(?P<close>[)\]}])",
            r"(?P<operator>[-+*/%<>=!~&|^@.])",
        ]
    )
)


def parse(text: str) -> ast.expr:
    """The tree of a scanned text; ExprSyntaxError (offsets into `text`) for bad or oversized text."""
    try:
        tree = ast.parse(text, mode="eval")
    except SyntaxError as exc:
        raise _syntax_error(text, exc) from None
    except (MemoryError, RecursionError, ValueError, OverflowError) as exc:
        message = f"the expression cannot be parsed: {type(exc).__name__}"
        raise ExprSyntaxError(message, 0, len(text)) from None
    _check_depth(text, tree.body)
    return tree.body


def _syntax_error(text: str, exc: SyntaxError) -> ExprSyntaxError:
    starts = line_starts(text)
    line = min(max(exc.lineno or 1, 1), len(starts))
    if not exc.offset:  # the parser reached the end of the text
        end = len(text.rstrip())
        return ExprSyntaxError(f"{exc.msg}: the expression ends too early", end, end)
    start = min(starts[line - 1] + exc.offset - 1, len(text))
    end = start + 1
    opened = _open_at(text, start) if exc.msg.startswith("closing parenthesis") else None
    if opened is not None:  # a closer that does not match: the opener is the one never closed
        message = f"'{text[opened]}' is never closed: '{text[start]}' stands where it should close"
        return ExprSyntaxError(message, opened, opened + 1)
    if exc.end_lineno and exc.end_offset and exc.end_offset > 0:
        end_line = min(exc.end_lineno, len(starts))
        end = max(end, min(starts[end_line - 1] + exc.end_offset - 1, len(text)))
    return ExprSyntaxError(exc.msg, start, end)


def _open_at(text: str, index: int) -> int | None:
    """The offset of the innermost bracket still open at text[index] (strings skipped)."""
    opened: list[int] = []
    for token in _TOKENS.finditer(text, 0, index):
        if token.lastgroup == "open":
            opened.append(token.start())
        elif token.lastgroup == "close" and opened:
            opened.pop()
    return opened[-1] if opened else None


def line_starts(text: str) -> list[int]:
    starts = [0]
    for i, char in enumerate(text):
        if char == "\n":
            starts.append(i + 1)
    return starts


def _check_depth(text: str, root: ast.expr) -> None:
    pending: list[tuple[ast.AST, int]] = [(root, 1)]
    while pending:
        node, depth = pending.pop()
        if depth > MAX_DEPTH:
            start, end = span(text, node)
            message = f"operations nested more than {MAX_DEPTH} deep in one expression (the limit)"
            raise ExprSyntaxError(message, start, end)
        for child in ast.iter_child_nodes(node):
            if isinstance(child, ast.expr):
                pending.append((child, depth + 1))


def span(text: str, node: ast.AST) -> tuple[int, int]:
    """The character offsets in `text` of a node (whose columns Python counts in UTF-8 bytes)."""
    starts = line_starts(text)
    return (
        _offset(text, starts, node.lineno, node.col_offset),  # type: ignore[attr-defined]
        _offset(text, starts, node.end_lineno, node.end_col_offset),  # type: ignore[attr-defined]
    )


def _offset(text: str, starts: list[int], line: int | None, col: int | None) -> int:
    if line is None or col is None:
        return 0
    begin = starts[min(line, len(starts)) - 1]
    end = len(text) if line >= len(starts) else starts[line]
    return begin + len(text[begin:end].encode("utf-8")[:col].decode("utf-8", "ignore"))
