"""Reading pack files as text the way the game does, and JSON with source positions.

- Function files are decoded as UTF-8 by a Java ``InputStreamReader``: an invalid byte becomes
  U+FFFD (the game does not refuse the file) and a byte order mark is *not* skipped, so it becomes
  part of the first command, which then fails to parse ("Unknown or incomplete command ... at
  position 0").
- JSON files (pack.mcmeta, tags, advancements) go through Gson, whose ``JsonReader`` skips a
  leading byte order mark.
- Lines split on ``\\n``, ``\\r\\n`` and ``\\r`` (``BufferedReader.lines()``), nothing else.
"""
from __future__ import annotations

import bisect
import json
import re
import zipfile
import zlib
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Union

from mcfunction_parser.diagnostics import ERROR, WARNING, Diagnostic, Loc

PackPath = Union[Path, zipfile.Path]  # a file or folder inside a pack folder or .zip
_READ_ERRORS = (OSError, zipfile.BadZipFile, zlib.error)

UTF8_BOM = b"\xef\xbb\xbf"
_LINE_BREAK = re.compile(r"\r\n|\r|\n")
_JSON_STRING = re.compile(r'"(?:[^"\\\r\n]|\\.)*"')


def split_lines(text: str) -> list[str]:
    """Lines without their terminators; a final terminator does not start an extra line."""
    lines = _LINE_BREAK.split(text) if "\r" in text else text.split("\n")  # split() is ~10x faster
    if len(lines) > 1 and lines[-1] == "":
        lines.pop()
    return lines


def read_text(path: PackPath, shown: str, diagnostics: list[Diagnostic], *, json_file: bool) -> str | None:
    """The file's text, or None if it cannot be read. Problems are appended as diagnostics."""
    try:
        data = path.read_bytes()
    except _READ_ERRORS as exc:
        diagnostics.append(Diagnostic(ERROR, f"cannot read file: {getattr(exc, 'strerror', None) or exc}", shown))
        return None
    if data.startswith(UTF8_BOM):
        data = data[len(UTF8_BOM):]
        if not json_file:
            diagnostics.append(Diagnostic(
                ERROR, "file starts with a UTF-8 byte order mark: the game reads it as part of "
                "the first command, which then fails to parse (save without BOM)", shown, 1, 1))
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        text = data.decode("utf-8", errors="replace")
        diagnostics.append(_invalid_utf8(data, exc.start, text, shown))
        return text


def _invalid_utf8(data: bytes, offset: int, text: str, shown: str) -> Diagnostic:
    before = data[:offset].decode("utf-8", errors="replace")
    line = len(split_lines(before + "x"))  # "x" so a break just before the byte counts
    col = len(before) - max(before.rfind("\n"), before.rfind("\r"))
    source_line = split_lines(text)[line - 1] if text else ""
    return Diagnostic(
        WARNING, f"invalid UTF-8 byte 0x{data[offset]:02x} at byte offset {offset}: the game "
        "reads it as U+FFFD (save the file as UTF-8)", shown, line, col, source_line)


@dataclass
class JsonDocument:
    """A parsed JSON file plus the positions of its string tokens, to point diagnostics at them."""

    path: str
    text: str
    value: Any
    _tokens: list[tuple[str, int]]  # (decoded string, offset), in file order
    _line_starts: list[int]

    def __post_init__(self) -> None:
        self._offsets = [offset for _, offset in self._tokens]

    def loc_at(self, offset: int) -> Loc:
        index = bisect.bisect_right(self._line_starts, offset) - 1
        return Loc(self.path, index + 1, offset - self._line_starts[index] + 1)

    def line_text(self, line: int) -> str:
        start = self._line_starts[line - 1]
        end = self._line_starts[line] if line < len(self._line_starts) else len(self.text)
        return self.text[start:end].rstrip("\r\n")

    def find_string(self, value: str, after: int = -1) -> int:
        """Offset of the first string token equal to ``value`` starting after ``after``; -1 if none."""
        tokens = self._tokens
        for index in range(bisect.bisect_right(self._offsets, after), len(tokens)):
            if tokens[index][0] == value:
                return tokens[index][1]
        return -1

    def diagnostic(self, severity: str, message: str, offset: int) -> Diagnostic:
        """A diagnostic at ``offset``; ``offset`` -1 (not found) points at the start of the file."""
        loc = self.loc_at(max(offset, 0))
        return Diagnostic.at(severity, message, loc, self.line_text(loc.line))


def load_json(path: PackPath, shown: str, diagnostics: list[Diagnostic]) -> JsonDocument | None:
    """Parse a JSON file; a syntax error becomes a diagnostic with its line and column."""
    text = read_text(path, shown, diagnostics, json_file=True)
    if text is None:
        return None
    line_starts = [0] + [m.end() for m in _LINE_BREAK.finditer(text)]
    try:
        value = json.loads(text)
    except json.JSONDecodeError as exc:
        doc = JsonDocument(shown, text, None, [], line_starts)
        diagnostics.append(doc.diagnostic(ERROR, f"invalid JSON: {exc.msg}", exc.pos))
        return None
    return json_document(value, shown, text)


def json_document(value, shown: str, text: str | None = None) -> JsonDocument:
    """A document of an already parsed value (``text``: its JSON as written, else made from it)."""
    text = json.dumps(value) if text is None else text
    line_starts = [0] + [m.end() for m in _LINE_BREAK.finditer(text)]
    tokens = [(_decode_token(m.group()), m.start()) for m in _JSON_STRING.finditer(text)]
    return JsonDocument(shown, text, value, tokens, line_starts)


def _decode_token(token: str) -> str:
    try:
        return json.loads(token)
    except json.JSONDecodeError:
        return token[1:-1]
