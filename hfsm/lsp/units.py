"""Columns as the client counts them: LSP positions count UTF-16 code units unless the client and
the server agreed on UTF-8 or UTF-32 at initialization (pygls makes that choice). Everything inside
the server counts characters (code points), as the terminal's `FILE:LINE:COL` does; positions are
turned into the client's units on the way out, and back on the way in."""

from __future__ import annotations

from collections.abc import Sequence

from lsprotocol import types as lsp
from pygls.workspace.position_codec import PositionCodec


class Units:
    def __init__(self, codec: PositionCodec) -> None:
        self.codec = codec

    @property
    def same(self) -> bool:
        """Whether the client counts characters too (UTF-32): nothing to convert."""
        return self.codec.encoding == lsp.PositionEncodingKind.Utf32

    def position_in(self, lines: Sequence[str], pos: lsp.Position) -> lsp.Position:
        """A client's position, in characters."""
        if self.same or pos.line >= len(lines):
            return pos
        line = lines[pos.line]
        units = chars = 0
        for char in line:
            if units >= pos.character:
                break
            units += self.codec.impl.code_units_for_char(char)
            chars += 1
        return lsp.Position(pos.line, chars)

    def range_in(self, lines: Sequence[str], rng: lsp.Range) -> lsp.Range:
        return lsp.Range(self.position_in(lines, rng.start), self.position_in(lines, rng.end))

    def position_out(self, lines: Sequence[str], pos: lsp.Position) -> lsp.Position:
        """A position in characters, in the client's units."""
        if self.same or pos.line >= len(lines):
            return pos
        return lsp.Position(pos.line, self.codec.client_num_units(lines[pos.line][: pos.character]))

    def range_out(self, lines: Sequence[str], rng: lsp.Range) -> lsp.Range:
        return lsp.Range(self.position_out(lines, rng.start), self.position_out(lines, rng.end))

    def symbols_out(self, lines: Sequence[str], found: list[lsp.DocumentSymbol]) -> list[lsp.DocumentSymbol]:
        for symbol in found:
            symbol.range = self.range_out(lines, symbol.range)
            symbol.selection_range = self.range_out(lines, symbol.selection_range)
            if symbol.children:
                self.symbols_out(lines, list(symbol.children))
        return found
