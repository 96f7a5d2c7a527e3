"""A cursor over one command's text with Brigadier's token rules.

Arguments are separated by exactly one space (Brigadier's ``ARGUMENT_SEPARATOR``). Tokens are
read with precompiled regexes matched at the cursor; a syntax error raises :class:`ParseError`
carrying the offset, which the command entry point turns into one diagnostic. Exceptions are
only raised for bad input, never on the happy path.
"""
from __future__ import annotations

import re
from bisect import bisect_right
from operator import itemgetter

from .diagnostics import Loc, new_loc
from .features import feature_problem

INT_MIN = -(2**31)
INT_MAX = 2**31 - 1

WORD = re.compile(r"[^ ]*")
_SPACED_WORD = re.compile(r" ([^ ]+)")
_SPACED_WORD_THEN_ARG = re.compile(r" ([^ ]+) (?=.)")
_WORD_THEN_ARG = re.compile(r"([^ ]+) (?=.)")
# Brigadier StringReader.isAllowedInUnquotedString
UNQUOTED = re.compile(r"[0-9A-Za-z_\-.+]*")
# Brigadier StringReader.isAllowedNumber: digits, '-' and '.'
NUMBER = re.compile(r"[0-9.\-]*")
# Brigadier quoted strings escape only the quote and the backslash.
QUOTED = {
    '"': re.compile(r'"((?:[^"\\]|\\["\\])*)"'),
    "'": re.compile(r"'((?:[^'\\]|\\['\\])*)'"),
}
_UNESCAPE = re.compile(r"\\(.)")
# a whole token that Integer.parseInt / Double.parseDouble accept (within Brigadier's number characters)
INT_TEXT = re.compile(r"-?[0-9]+\Z")
FLOAT_TEXT = re.compile(r"-?(?:[0-9]+\.?[0-9]*|\.[0-9]+)\Z")


class ParseError(Exception):
    """A syntax error at offset ``pos`` of the command text."""

    def __init__(self, message: str, pos: int):
        super().__init__(message)
        self.message = message
        self.pos = pos


def show(text: str) -> str:
    """How an offending token appears in a message."""
    return f"'{brief(text)}'" if text else "end of command"


_BRIEF = 40


def brief(token: str) -> str:
    """A token short enough for a message: a 1,000,000-digit literal shows its start and length."""
    if len(token) <= _BRIEF:
        return token
    return f"{token[:_BRIEF // 2]}... ({len(token)} characters)"


# Past this many digits a literal is out of every range the game has (a long has 19 digits), so it is
# never converted: int() of a huge string is slow and, past sys.get_int_max_str_digits(), refused.
_MAX_DIGITS = 64


def integer_value(digits: str, base: int = 10) -> int:
    """``int(digits, base)``, or a value past every NBT and argument range for a very long literal
    (the callers' range checks then report it as out of range, at its column)."""
    if len(digits) <= _MAX_DIGITS:
        return int(digits, base)
    return -(2 ** 256) if digits.lstrip().startswith("-") else 2 ** 256


class Reader:
    """The command text, the cursor, and how offsets map back to file positions."""

    __slots__ = ("text", "pos", "end", "start_loc", "path", "line", "col", "version", "warnings")

    def __init__(self, text: str, loc: Loc, version: tuple[int, int, int]):
        self.text = text
        self.start_loc = loc  # where the text starts: the location of a command at offset 0
        self.pos = 0
        self.end = len(text)
        self.path, self.line, self.col = loc  # a named tuple: unpacked faster than read by name
        self.version = version
        self.warnings: list[tuple[str, int]] = []  # (message, offset): problems that keep the command

    # ------------------------------------------------------------------ positions

    def loc(self) -> Loc:
        """The file position of the cursor."""
        return new_loc((self.path, self.line, self.col + self.pos))

    def loc_at(self, pos: int) -> Loc:
        return new_loc((self.path, self.line, self.col + pos))

    def fail(self, message: str, pos: int | None = None):
        raise ParseError(message, self.pos if pos is None else pos)

    def require(self, feature: str, pos: int) -> None:
        """Fail at ``pos`` when ``feature`` (a key of features.FEATURES) is not in the target version."""
        problem = feature_problem(feature, self.version)
        if problem:
            self.fail(problem, pos)

    # ------------------------------------------------------------------ structure

    def more(self) -> bool:
        return self.pos < self.end

    def peek(self) -> str:
        return self.text[self.pos] if self.pos < self.end else ""

    def skip_ws(self) -> None:
        """Skip Java whitespace (inside SNBT, JSON and selector brackets)."""
        text, pos, end = self.text, self.pos, self.end
        while pos < end and text[pos] in " \t\r\n":
            pos += 1
        self.pos = pos

    def expect(self, char: str) -> None:
        if self.pos < self.end and self.text[self.pos] == char:
            self.pos += 1
            return
        self.fail(f"expected '{char}', got {self.found()}")

    def space(self, what: str = "an argument") -> None:
        """Consume the one space before a required argument."""
        pos = self.pos
        if pos < self.end and self.text[pos] == " ":
            if pos + 1 < self.end:
                self.pos = pos + 1
                return
            self.fail(f"expected {what} after the space, got end of command", pos + 1)
        if pos >= self.end:
            self.fail(f"incomplete command: expected {what}")
        self.fail(f"expected whitespace to end the argument, got {self.found()}")

    def optional_space(self) -> bool:
        """True (and the space consumed) when another argument follows."""
        pos = self.pos
        if pos >= self.end:
            return False
        if self.text[pos] == " " and pos + 1 < self.end:
            self.pos = pos + 1
            return True
        if self.text[pos] == " ":
            self.fail("trailing space after the last argument", pos)
        self.fail(f"expected whitespace to end the argument, got {self.found()}")

    def finish(self) -> None:
        """The command must end here."""
        if self.pos < self.end:
            if self.text[self.pos] != " ":
                self.fail(f"expected whitespace to end the argument, got {self.found()}")
            extra = self.rest_word(self.pos + 1)
            if extra:
                self.fail(f"expected end of command, got '{extra}'", self.pos + 1)
            self.fail("unexpected space: arguments are separated by exactly one space", self.pos)

    def found(self) -> str:
        """What is at the cursor, for "expected X, got Y" messages."""
        if self.pos >= self.end:
            return "end of command"
        if self.text[self.pos] == " ":
            return "a second space (arguments are separated by exactly one space)"
        return f"'{self.rest_word()}'"

    def rest_word(self, pos: int | None = None) -> str:
        return WORD.match(self.text, self.pos if pos is None else pos).group()

    def rest(self) -> str:
        text = self.text[self.pos:]
        self.pos = self.end
        return text

    # ------------------------------------------------------------------ tokens

    def word(self) -> str:
        m = WORD.match(self.text, self.pos)
        self.pos = m.end()
        return m.group()

    def literal(self, choices, what: str) -> str:
        """One of ``choices`` (a set or dict of words)."""
        start = self.pos
        word = WORD.match(self.text, start).group()
        if word in choices:
            self.pos = start + len(word)
            return word
        options = "|".join(sorted(choices))
        self.fail(f"expected {what} ({options}), got {show(word) if word else self.found()}", start)

    def keyword(self, choices, what: str) -> str:
        """The space before a required literal and the literal itself (one of ``choices``)."""
        m = _SPACED_WORD.match(self.text, self.pos)
        if m is not None:
            word = m.group(1)
            if word in choices:
                self.pos = m.end()
                return word
        self.space(what)
        return self.literal(choices, what)

    def keyword_then_space(self, choices, what: str, next_what) -> str:
        """:meth:`keyword` and the space before the argument that must follow it;
        ``next_what(word)`` names that argument in the error message."""
        m = _SPACED_WORD_THEN_ARG.match(self.text, self.pos)
        if m is not None:
            word = m.group(1)
            if word in choices:
                self.pos = m.end()
                return word
        word = self.keyword(choices, what)
        self.space(next_what(word))
        return word

    def word_then_space(self, choices, what: str, next_what) -> str:
        """:meth:`literal` and the space before the argument that must follow it."""
        m = _WORD_THEN_ARG.match(self.text, self.pos)
        if m is not None:
            word = m.group(1)
            if word in choices:
                self.pos = m.end()
                return word
        word = self.literal(choices, what)
        self.space(next_what(word))
        return word

    def unquoted(self) -> str:
        m = UNQUOTED.match(self.text, self.pos)
        self.pos = m.end()
        return m.group()

    def quoted(self) -> str:
        start = self.pos
        quote = self.text[start]
        m = QUOTED[quote].match(self.text, start)
        if m is None:
            self._quoted_error(start, quote)
        self.pos = m.end()
        body = m.group(1)
        return _UNESCAPE.sub(r"\1", body) if "\\" in body else body

    def _quoted_error(self, start: int, quote: str):
        text, pos = self.text, start + 1
        while pos < self.end:
            c = text[pos]
            if c == "\\":
                if pos + 1 < self.end and text[pos + 1] in (quote, "\\"):
                    pos += 2
                    continue
                self.fail(f"invalid escape sequence '\\{text[pos + 1:pos + 2]}' in quoted string", pos)
            if c == quote:
                break
            pos += 1
        self.fail("unclosed quoted string", start)

    def string(self) -> str:
        """Brigadier ``readString``: a quoted string, or an unquoted word."""
        c = self.peek()
        if c == '"' or c == "'":
            return self.quoted()
        return self.unquoted()

    def integer(self, lo: int = INT_MIN, hi: int = INT_MAX, what: str = "integer") -> int:
        start = self.pos
        token = NUMBER.match(self.text, start).group()
        if not token:
            self.fail(f"expected {what}, got {self.found()}")
        if not INT_TEXT.match(token):
            self.fail(f"invalid integer '{token}'", start)
        value = integer_value(token)
        if value < INT_MIN or value > INT_MAX:
            self.fail(f"integer {brief(token)} is out of range for a 32-bit int", start)
        if value < lo:
            self.fail(f"{what} must be at least {lo}, got {value}", start)
        if value > hi:
            self.fail(f"{what} must be at most {hi}, got {value}", start)
        self.pos = start + len(token)
        return value

    def double(self, lo: float | None = None, hi: float | None = None, what: str = "number") -> float:
        start = self.pos
        token = NUMBER.match(self.text, start).group()
        if not token:
            self.fail(f"expected {what}, got {self.found()}")
        if not FLOAT_TEXT.match(token):
            self.fail(f"invalid number '{token}'", start)
        value = float(token)
        if lo is not None and value < lo:
            self.fail(f"{what} must be at least {lo:g}, got {token}", start)
        if hi is not None and value > hi:
            self.fail(f"{what} must be at most {hi:g}, got {token}", start)
        self.pos = start + len(token)
        return value

    def boolean(self) -> bool:
        start = self.pos
        word = self.string()
        if word == "true":
            return True
        if word == "false":
            return False
        self.fail(f"expected true or false, got {show(word)}", start)


_first = itemgetter(0)


class JoinedReader(Reader):
    """A command joined from continuation lines: ``segments`` lists ``(offset, line, col)`` where
    each physical line's piece starts, so positions map back to the right line."""

    __slots__ = ("segments", "offsets")

    def __init__(self, text: str, loc: Loc, version: tuple[int, int, int], segments: tuple):
        super().__init__(text, loc, version)
        self.segments = segments
        self.offsets = list(map(_first, segments))  # ascending, the first 0

    def loc(self) -> Loc:
        return self.loc_at(self.pos)

    def loc_at(self, pos: int) -> Loc:
        start, line, col = self.segments[bisect_right(self.offsets, pos) - 1]  # the last piece starting at or before pos
        return new_loc((self.path, line, col + pos - start))
