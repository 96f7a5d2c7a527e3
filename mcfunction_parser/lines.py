"""Split a function file into logical command lines, as the game's function loader does.

Each physical line is trimmed (Java ``String.trim``: every character up to U+0020); an empty
line or one starting with ``#`` is skipped. From 1.20.2 a trimmed line ending in ``\\`` is
joined with the next trimmed line (the ``\\`` removed; this also applies to comment lines), and
a line starting with ``$`` is a macro line whose ``$(key)`` placeholders are filled in when
the function is called with arguments.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from .features import FEATURES

TRIM = "".join(chr(c) for c in range(0x21))
MAX_COMMAND_LENGTH = 2_000_000  # CommandFunction.checkCommandLineLength
_MACRO_VAR = re.compile(r"\$\(([^)]*)\)?")
_MACRO_KEY = re.compile(r"[A-Za-z0-9_]+\Z")


@dataclass(frozen=True, slots=True)
class LineError:
    message: str
    line: int
    col: int


def logical_lines(physical: list[str], version: tuple[int, int, int]):
    """Yield ``(text, line, col, segments)`` for each command or ``$`` line, and :class:`LineError`.

    ``segments`` is empty for a one-line command; for a joined one it maps offsets back to
    ``(offset, line, col)`` of each physical piece. (:func:`.parse.parse_lines` runs the same loop
    inline, the generator's frame switch per line being a tenth of a trivial line's parse.)
    """
    continuation = version >= FEATURES["line continuation"][0]
    count = len(physical)
    i = 0
    while i < count:
        raw = physical[i]
        i += 1
        text = raw.strip(TRIM)
        if not text:
            continue
        if (continuation and text[-1] == "\\") or len(text) > MAX_COMMAND_LENGTH:
            item, i = unusual_line(physical, i - 1, text, continuation)
            if item is not None:
                yield item
            continue
        if text[0] == "#":
            continue
        yield text, i, (1 if raw[0] > " " else len(raw) - len(raw.lstrip(TRIM)) + 1), ()


def unusual_line(physical: list[str], first: int, text: str, continuation: bool):
    """``(item, next index)`` for the trimmed line ``text`` at index ``first`` that ends in ``\\`` (with
    ``continuation``) or is too long: the item a :class:`LineError`, a joined command's
    ``(text, line, col, segments)``, or None for a joined comment."""
    if continuation and text[-1] == "\\":
        joined = _join(physical, first, text)
        if type(joined) is LineError:
            return joined, len(physical)
        text, segments, i = joined
        if len(text) > MAX_COMMAND_LENGTH:
            return _too_long(text, segments[0][1], segments[0][2]), i
        if text and text[0] != "#":
            return (text, segments[0][1], segments[0][2], segments), i
        return None, i
    return _too_long(text, first + 1, 1), first + 1  # checked before comments are skipped, as the game does


def _too_long(text: str, line: int, col: int) -> LineError:
    return LineError(f"command too long: {len(text)} characters (at most {MAX_COMMAND_LENGTH})", line, col)


def _join(physical: list[str], first: int, text: str):
    """Join the continuation lines from ``first``: (text, segments, next index) or a LineError."""
    raw = physical[first]
    col = len(raw) - len(raw.lstrip(TRIM)) + 1
    pieces = [text[:-1]]
    segments = [(0, first + 1, col)]
    offset = len(text) - 1
    i = first + 1
    while True:
        if i == len(physical):
            return LineError("line continuation '\\' at the end of the file", first + 1, col + len(text) - 1)
        nxt = physical[i]
        piece = nxt.strip(TRIM)
        segments.append((offset, i + 1, len(nxt) - len(nxt.lstrip(TRIM)) + 1))
        i += 1
        if not piece.endswith("\\"):
            pieces.append(piece)
            return "".join(pieces), tuple(segments), i
        pieces.append(piece[:-1])
        offset += len(piece) - 1


def macro_keys(template: str) -> tuple[tuple[str, ...], str | None, int]:
    """The ``$(key)`` names of a macro line's template, and an error message with its offset if invalid."""
    keys: list[str] = []
    for m in _MACRO_VAR.finditer(template):
        if not m.group(0).endswith(")"):
            return (), "unterminated macro variable '$(' (expected ')')", m.start()
        key = m.group(1)
        if not _MACRO_KEY.match(key):
            return (), f"invalid macro variable name '{key}' (allowed: A-Z a-z 0-9 _)", m.start() + 2
        if key not in keys:
            keys.append(key)
    if not keys:
        return (), "macro line without any $(variable)", 0
    return tuple(keys), None, 0
