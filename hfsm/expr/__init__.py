"""Expressions (docs/REFERENCE.md#expressions): what they may read (scope), how they are compiled (compiler),
what
they do when they run (ops), and values as text (text)."""

from hfsm.expr.compiler import TIMED, compile_expr, reads, reads_at
from hfsm.expr.ops import bounded
from hfsm.expr.scope import NOWHERE, ExprSyntaxError, ExprValueError, Fn, Live, Names, Scope
from hfsm.expr.text import format_number, short, to_text

__all__ = [
    "NOWHERE",
    "TIMED",
    "ExprSyntaxError",
    "ExprValueError",
    "Fn",
    "Live",
    "Names",
    "Scope",
    "bounded",
    "compile_expr",
    "format_number",
    "reads",
    "reads_at",
    "short",
    "to_text",
]
