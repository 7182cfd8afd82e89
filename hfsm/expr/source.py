"""The text of an expression as Python parses it, and the way back to the text as written.

`in.x` is written where Python expects the keyword `in`: it is renamed `__in__.x` before parsing
(not the operator `a in b`). Errors and nodes are then located in the text as written: the offsets
of the renamed text are mapped back, past the stripped leading spaces and each renaming.
"""

from __future__ import annotations

import ast
import io
import tokenize
from bisect import bisect_right
from dataclasses import dataclass

from hfsm.expr import guard
from hfsm.expr.scope import IN, ExprSyntaxError

_OPERANDS = (tokenize.NUMBER, tokenize.STRING)
_KEYWORDS = {"and", "or", "not", "in", "if", "else", "is", "lambda"}
_GROWTH = len(IN) - len("in")
@dataclass(frozen=True)
class Source:
    written: str  # as given
    lead: int  # spaces stripped before it
    text: str  # stripped, `in.` renamed
    cuts: tuple[int, ...]  # where `in.` was renamed, as offsets in `text`

    @classmethod
    def of(cls, written: str) -> Source:
        """Scan (hfsm.expr.guard) and rename; ExprSyntaxError with offsets in `written`."""
        stripped = written.strip()
        lead = len(written) - len(written.lstrip())
        try:
            guard.scan(stripped)
            text, cuts = _inputs_renamed(stripped)
        except ExprSyntaxError as exc:
            raise exc.shifted(lead) from None
        return cls(written, lead, text, cuts)

    def parse(self) -> ast.expr:
        try:
            return guard.parse(self.text)
        except ExprSyntaxError as exc:
            start = self.back(exc.start or 0)
            raise ExprSyntaxError(exc.message, start, max(start, self.back(exc.end or 0))) from None

    def back(self, offset: int) -> int:
        """An offset in `text` as an offset in `written`."""
        before = bisect_right(self.cuts, offset) - 1  # the renaming at or before the offset
        if before >= 0 and offset < self.cuts[before] + len(IN):
            return self.lead + self.cuts[before] - _GROWTH * before + min(offset - self.cuts[before], 2)
        return self.lead + offset - _GROWTH * (before + 1)

    def where(self, node: ast.AST) -> tuple[int, int]:
        start, end = guard.span(self.text, node)
        return self.back(start), self.back(end)


def _tokens(source: str) -> list[tokenize.TokenInfo]:
    """The tokens up to the first error, if any (the parser reports it)."""
    tokens = []
    try:
        for token in tokenize.generate_tokens(io.StringIO(source).readline):
            if token.type != tokenize.NL:
                tokens.append(token)
    except (tokenize.TokenError, SyntaxError):
        pass
    return tokens


def _inputs_renamed(source: str) -> tuple[str, tuple[int, ...]]:
    """`in.x` as `__in__.x`, where `in` stands as an operand (not the operator `a in b`)."""
    if "in" not in source:
        return source, ()
    tokens = _tokens(source)
    starts = guard.line_starts(source)
    found = []
    for i, tok in enumerate(tokens):
        if tok.type != tokenize.NAME or tok.string not in ("in", IN):
            continue
        at = starts[tok.start[0] - 1] + tok.start[1]
        if tok.string == IN:
            raise ExprSyntaxError(f"unknown name '{IN}'", at, at + len(IN))
        if i + 1 >= len(tokens) or tokens[i + 1].string != ".":
            continue
        before = tokens[i - 1] if i else None
        operand_before = before is not None and (
            before.type in _OPERANDS
            or before.string in (")", "]", "}")
            or (before.type == tokenize.NAME and before.string not in _KEYWORDS)
        )
        if not operand_before:
            found.append(at)
    for at in reversed(found):
        source = source[:at] + IN + source[at + 2 :]
    return source, tuple(at + _GROWTH * i for i, at in enumerate(found))
