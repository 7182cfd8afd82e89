"""Quick fixes: every finding that carries a suggestion (`did you mean 'x'?`, `write '...'`)
offers to make it, in place of what the finding underlines."""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence

from lsprotocol import types as lsp

_MEANT = re.compile(r"did you mean (.+)\?")
_QUOTED = re.compile(r"(?:\b\w+ )?'([^']+)'")
_WRITE = re.compile(r"[;:] write '(.+?)'(?: for an expression)?$")


def suggestions(message: str) -> list[str]:
    """The replacements a message suggests, best first."""
    found: list[str] = []
    meant = _MEANT.search(message)
    if meant is not None:
        found += _QUOTED.findall(meant.group(1))
    wrap = _WRITE.search(message)
    if wrap is not None:
        found.append(wrap.group(1))
    return found


def quick_fixes(
    uri: str,
    lines: Sequence[str],
    diagnostics: Sequence[lsp.Diagnostic],
    inward: Callable[[lsp.Range], lsp.Range] = lambda r: r,
) -> list[lsp.CodeAction]:
    """`inward`: a diagnostic's range (in the client's units) in characters, to read what it covers."""
    actions: list[lsp.CodeAction] = []
    for diagnostic in diagnostics:
        if diagnostic.source != "hfsm" or diagnostic.related_information:
            continue  # another tool's, or a callee's errors (their fixes are in the callee's file)
        old = _text(lines, inward(diagnostic.range))
        for new in suggestions(diagnostic.message):
            if old[:1] in "'\"" and old[:1] and not new.startswith(old[:1]):
                new = f"{old[0]}{new}{old[0]}"  # keep the quotes the value was written in
            edit = lsp.TextEdit(range=diagnostic.range, new_text=new)
            actions.append(
                lsp.CodeAction(
                    title=f"Replace with '{new}'",
                    kind=lsp.CodeActionKind.QuickFix,
                    diagnostics=[diagnostic],
                    edit=lsp.WorkspaceEdit(changes={uri: [edit]}),
                    is_preferred=len(actions) == 0,
                )
            )
    return actions


def _text(lines: Sequence[str], rng: lsp.Range) -> str:
    line = lines[rng.start.line] if rng.start.line < len(lines) else ""
    return line[rng.start.character : rng.end.character]
