"""Dispatch on a command's first word; every command family registers its parsers here."""
from __future__ import annotations

from ..ast import Command
from ..dialect import packtest_enabled
from ..features import COMMANDS, command_problem, permission_warning
from ..reader import Reader
from ..relocate import READ, READ_MAX, NotRelocatable, relocate
from .tree import tree_command

# name -> parser(reader positioned after the name, loc of the name) -> Command
REGISTRY: dict = {}
# PackTest's commands, read where it is loaded (mcfunction_parser.dialect; commands.packtest registers them)
PACKTEST: dict = {}


_TABLES: dict = {}  # version -> its table, built on first use (after every family has registered)


_LAST = [None, None]  # the release read last (the same tuple, line after line) and its table


def _table(version: tuple[int, int, int]) -> dict:
    """The commands of ``version``: name -> (parser, or None for one the command tree checks; warning or None)."""
    table = _TABLES.get(version)
    if table is None:
        table = _TABLES[version] = {name: (REGISTRY.get(name), permission_warning(name))
                                    for name in COMMANDS if command_problem(name, version) is None}
    _LAST[:] = version, table
    return table


def command(r: Reader) -> Command:
    """Parse the command starting at the cursor (the rest of the text)."""
    start = r.pos
    text = r.text
    space = text.find(" ", start)
    name = text[start:space] if space >= 0 else text[start:]
    version = r.version
    table = _LAST[1] if version is _LAST[0] else _table(version)
    entry = table.get(name)
    if entry is None:
        if not name:
            r.fail(f"expected a command, got {r.found()}")
        if name in PACKTEST:
            if packtest_enabled():
                r.pos = start + len(name)
                return PACKTEST[name](r, r.start_loc if start == 0 else r.loc_at(start))
            r.fail(f"unknown command '{name}' (PackTest's: known where the PackTest mod runs, as in "
                   "`dpemu test` or `dpemu check --packtest`)", start)
        r.fail(command_problem(name, r.version), start)
    loc = r.start_loc if start == 0 else r.loc_at(start)
    r.pos = start + len(name)
    parser, warning = entry
    if warning:
        r.warnings.append((warning, start))
    if parser is not None:
        return parser(r, loc)
    return tree_command(r, loc, name)


def rest_command(r: Reader) -> Command:
    """The command that is the rest of the text (after ``execute ... run``, ``return run``): when
    that text was read cleanly before as a line or such a rest (see relocate.READ), the command
    read then, moved here; else read, and remembered when it read cleanly to the end."""
    read = READ.get(r.version) if type(r) is Reader else None  # a joined line's offsets span lines
    if read is None:
        return command(r)
    start = r.pos
    rest = r.text[start:]
    known = read.get(rest)
    col = r.col + start
    if known:
        try:
            found = relocate(known[0], r.path, r.line, col - known[1])
            r.pos = r.end
            return found
        except NotRelocatable:
            read[rest] = False
            known = False
    warned = len(r.warnings)
    found = command(r)
    if known is None and r.pos == r.end and len(r.warnings) == warned and len(read) < READ_MAX:
        read[rest] = (found, col)
    return found
