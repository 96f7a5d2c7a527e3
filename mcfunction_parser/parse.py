"""Public entry points: parse one function file, or one command (a macro line after substitution)."""
from __future__ import annotations

import contextlib
import gc
import re

from .ast import Command, Function, MacroLine, UnreadCommand
from .commands import command
from .commands.tree import newer_than_every_tree, stand_in_note
from .diagnostics import ERROR, WARNING, Diagnostic, Loc, new_loc
from .features import FEATURES, feature_problem
from .lines import MAX_COMMAND_LENGTH, TRIM, LineError, macro_keys, unusual_line
from .reader import JoinedReader, ParseError, Reader
from .relocate import NotRelocatable, lines_read, relocate
from .relocate import forget_read_lines  # noqa: F401  (the parser's public entry points are here)

DEFAULT_VERSION = (1, 21, 0)
_LINE_BREAK = re.compile(r"\r\n|\r|\n")
_BOM = "\ufeff"


def parse_function(source: str, path: str, function_id: str,
                   version: tuple[int, int, int] = DEFAULT_VERSION) -> tuple[Function, list[Diagnostic]]:
    """Parse a whole .mcfunction file. A bad line is reported and left out; the rest still parses.

    (The game itself refuses to load a function with any bad line.)
    """
    # the game reads lines with BufferedReader: '\n', '\r' and '\r\n' all end a line
    physical = _LINE_BREAK.split(source) if "\r" in source else source.split("\n")
    if physical[-1] == "":
        physical.pop()
    return parse_lines(physical, path, function_id, version)


def parse_lines(physical: list[str], path: str, function_id: str,
                version: tuple[int, int, int] = DEFAULT_VERSION, pack: str = "") -> tuple[Function, list[Diagnostic]]:
    """:func:`parse_function` of a file already split into its lines (without their terminators,
    as the pack loader keeps them for diagnostics); ``physical`` is not modified. ``pack``: the
    root of the pack the file is in (``Function.pack``).

    What it builds is moved to the collector's oldest generation (``kept``): a function's nodes hold
    no reference cycles, so the young-generation pass over all of them that would follow the pause
    (about 7 % of the parse) finds nothing; unreferenced, they are freed by their counts as ever."""
    with paused_gc(kept=True):
        return _parse_lines(physical, path, function_id, version, pack)


@contextlib.contextmanager
def paused_gc(kept: bool = False):
    """The cyclic garbage collector paused inside the block (and resumed after, if it was running).

    The parser builds many small objects and no reference cycles, so the collector only re-walks
    the growing AST: paused, a 40,000-line file parses about twice as fast, and loading or checking
    a hundred packs spends no time re-walking the functions already parsed. ``kept``: what the
    block builds stays (a check's loaded packs): on resuming, the collector's objects are moved to
    its oldest generation (``gc.freeze`` then ``gc.unfreeze``), where they would be had it run all
    along; left in the youngest, its next collection would walk them all (seconds, for a million
    commands)."""
    collecting = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if collecting:
            if kept:
                gc.freeze()
                gc.unfreeze()
            gc.enable()


def _parse_lines(physical: list[str], path: str, function_id: str,
                 version: tuple[int, int, int], pack: str) -> tuple[Function, list[Diagnostic]]:
    commands: list[Command] = []
    diagnostics: list[Diagnostic] = []
    if physical and physical[0].startswith(_BOM):
        # Java keeps the byte order mark as a character (trim() doesn't remove it), so the game fails
        # on the first line; it is reported once here and the rest is parsed without it
        physical = [physical[0][1:], *physical[1:]]
        diagnostics.append(Diagnostic(ERROR, "the file starts with a byte order mark (U+FEFF), which the game "
                                      "reads as part of the first line", path, 1, 1, physical[0]))
    is_macro = False
    macros_ok = feature_problem("macro lines", version) is None
    read = lines_read(version)
    continuation = version >= FEATURES["line continuation"][0]
    count = len(physical)
    i = 0
    while i < count:  # lines.logical_lines, inline
        raw = physical[i]
        i += 1
        text = raw.strip(TRIM)
        if not text:
            continue
        if (continuation and text[-1] == "\\") or len(text) > MAX_COMMAND_LENGTH:
            item, i = unusual_line(physical, i - 1, text, continuation)
            if item is None:
                continue
            if type(item) is LineError:
                diagnostics.append(Diagnostic(ERROR, item.message, path, item.line, item.col,
                                              physical[item.line - 1]))
                continue
            text, line, col, segments = item
        elif text[0] == "#":
            continue
        else:
            line, col, segments = i, (1 if raw[0] > " " else len(raw) - len(raw.lstrip(TRIM)) + 1), ()
        if not segments:  # a joined line spans lines: read each time
            known = read.get(text)
            if known:  # the same text read cleanly before: the same command, moved here
                try:
                    commands.append(relocate(known[0], path, line, col - known[1]))
                    continue
                except NotRelocatable:
                    read[text] = False
        loc = new_loc((path, line, col))
        first = text[0]
        if first == "$":
            if not macros_ok:
                diagnostics.append(Diagnostic(ERROR, feature_problem("macro lines", version), path, line, col,
                                              physical[line - 1]))
                continue
            macro = _macro_line(text, loc, segments, physical, diagnostics)
            if macro is not None:
                commands.append(macro)
                is_macro = True
            continue
        if first == "/":
            _leading_slash(text, loc, physical, diagnostics)
            continue
        if segments:
            cmd = _parse(JoinedReader(text, loc, version, segments), diagnostics, physical, keep_unread=True)
        else:
            found = len(diagnostics)
            cmd = _parse(Reader(text, loc, version), diagnostics, physical, keep_unread=True)
            if known is None and len(diagnostics) == found and cmd is not None:  # False: kept
                read[text] = (cmd, col)
        if cmd is not None:
            commands.append(cmd)
    function = Function.new(function_id, path, tuple(commands), len(physical), is_macro, pack)
    return function, diagnostics


def parse_command(text: str, loc: Loc,
                  version: tuple[int, int, int] = DEFAULT_VERSION) -> tuple[Command | None, list[Diagnostic]]:
    """Parse one command (no leading ``/``), e.g. a macro line with its ``$(key)`` filled in.

    ``loc`` is where the command text starts; diagnostics point into ``text`` from there. A
    command that does not parse is an error even in a release newer than every command tree: a
    macro line that fails to parse when it is called fails the call, which packs test for.
    """
    diagnostics: list[Diagnostic] = []
    source_line = " " * (loc.col - 1) + text
    reader = Reader(text, loc, version)
    cmd = _parse(reader, diagnostics, None, source_line)
    return cmd, diagnostics


def _parse(reader: Reader, diagnostics: list[Diagnostic], physical: list[str] | None,
           source_line: str | None = None, keep_unread: bool = False) -> Command | None:
    try:
        cmd = command(reader)
        if reader.pos < reader.end:
            reader.finish()
    except ParseError as error:
        if keep_unread and newer_than_every_tree(reader.version):
            cmd = _unread(reader, error, diagnostics, physical)
        else:
            _report(reader, ERROR, error.message, error.pos, diagnostics, physical, source_line)
            cmd = None
    except RecursionError:
        _report(reader, ERROR, "command is nested too deeply", 0, diagnostics, physical, source_line)
        cmd = None
    for message, pos in reader.warnings:
        _report(reader, WARNING, message, pos, diagnostics, physical, source_line)
    return cmd


def _unread(reader: Reader, error: ParseError, diagnostics: list[Diagnostic],
            physical: list[str] | None) -> UnreadCommand:
    """A function's line the readers refuse, in a release newer than every command tree here
    (26.2), whose syntax may have changed: a warning, and the line kept as an
    :class:`UnreadCommand` so the function loads (elsewhere such a line is an error and the game
    refuses to load the function)."""
    reason = f"{error.message} ({stand_in_note(reader.version)})"
    _report(reader, WARNING, reason, error.pos, diagnostics, physical, None)
    return UnreadCommand.new(reader.start_loc, reader.text.split(" ", 1)[0], reader.text, reason)


def _report(reader: Reader, severity: str, message: str, pos: int, diagnostics: list[Diagnostic],
            physical: list[str] | None, source_line: str | None) -> None:
    loc = reader.loc_at(min(pos, reader.end))
    if physical is not None:
        source_line = physical[loc.line - 1]
    diagnostics.append(Diagnostic.at(severity, message, loc, source_line))


def _macro_line(text: str, loc: Loc, segments: tuple, physical: list[str],
                diagnostics: list[Diagnostic]) -> MacroLine | None:
    template = text[1:]
    keys, error, offset = macro_keys(template)
    if error:
        reader = JoinedReader(text, loc, (0, 0, 0), segments) if segments else Reader(text, loc, (0, 0, 0))
        _report(reader, ERROR, error, offset + 1, diagnostics, physical, None)
        return None
    return MacroLine.new(loc, template, keys)


def _leading_slash(text: str, loc: Loc, physical: list[str], diagnostics: list[Diagnostic]) -> None:
    if text.startswith("//"):
        message = "unknown command '//...': comments start with '#', not '//'"
    else:
        name = text[1:].split(" ", 1)[0]
        message = f"unknown command '{text.split(' ', 1)[0]}': remove the leading '/' (did you mean '{name}'?)"
    diagnostics.append(Diagnostic.at(ERROR, message, loc, physical[loc.line - 1]))
