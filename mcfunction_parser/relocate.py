"""A parsed command moved to another line: the same nodes, every :class:`Loc` in them moved.

A command's parse depends only on its text and the release (the registries and command trees are
fixed per process), and its locations only on where the text starts. So :mod:`.parse` reads each
distinct line once per release and builds a repeated line by relocating the first one's nodes:
real packs repeat many lines (a quarter of the pool pack's command lines repeat an earlier one).

Relocating builds new nodes wherever a location is inside, and shares what holds none (ranges,
coordinates, names): those are immutable. A command holding a mutable value (an NBT compound or
list: ``summon ... {...}``, ``nbt=`` in a selector, ``data modify ... value``) is not relocated:
:class:`NotRelocatable` says so, and the caller parses such lines each time.
"""
from __future__ import annotations

import dataclasses

from .diagnostics import Loc, new_loc
from .frozen_init import ON_GUARD, build_lines, builder, is_frozen


# For the release read last, each command text read cleanly (no diagnostic) -> (its command, the
# column it started at), or False for one that cannot be relocated. A whole line seen again is
# relocated, not read again (a quarter of the pool pack's command lines repeat an earlier one), and
# so is the command after an ``execute ... run`` (see commands.dispatch.rest_command). A text that had
# a diagnostic is always read again, so it reports it again.
READ: dict[tuple[int, int, int], dict] = {}
READ_MAX = 1 << 15


def lines_read(version: tuple[int, int, int]) -> dict:
    """The memory of texts read for ``version``: one release at a time, and a bound on the nodes it
    keeps alive (past it, it starts afresh)."""
    read = READ.get(version)
    if read is None or len(read) >= READ_MAX:
        READ.clear()
        read = READ[version] = {}
    return read


def forget_read_lines() -> None:
    """Empty the memory of texts read (a benchmark's fresh start; a test's clean slate)."""
    READ.clear()


class NotRelocatable(Exception):
    """The node holds a value that must not be shared between two commands."""


def relocate(node, path: str, line: int, shift: int):
    """``node`` with each Loc ``(p, l, c)`` in it replaced by ``Loc(path, line, c + shift)``."""
    relocator = _RELOCATORS[type(node)]
    return node if relocator is None else relocator(node, path, line, shift)


def _loc(loc: Loc, path: str, line: int, shift: int) -> Loc:
    return new_loc((path, line, loc[2] + shift))


def _tuple(items: tuple, path: str, line: int, shift: int) -> tuple:
    moved = []
    changed = False
    for item in items:
        relocator = _RELOCATORS[type(item)]
        if relocator is not None:
            item = relocator(item, path, line, shift)
            changed = True
        moved.append(item)
    return tuple(moved) if changed else items


def _refuse(value, path, line, shift):
    raise NotRelocatable(type(value).__name__)


_IMMUTABLE = (str, int, float, type(None))  # bool is an int; NBT numbers and strings subclass these
# fields annotated so hold immutable values that hold no location: kept without a look
SCALARS = frozenset(("str", "int", "bool", "float", "str | None", "int | None", "float | None", "bool | None",
                     "tuple[str, ...]", "tuple[int, ...]"))


def _dataclass_relocator(cls: type):
    """A function rebuilding an instance of the frozen dataclass ``cls`` with its locations moved,
    None when its fields are all scalars (the instance is kept), or :func:`_refuse` for a class
    that its constructor cannot rebuild from the field values in order."""
    fields = dataclasses.fields(cls)
    if any(not f.init or f.kw_only for f in fields):
        return _refuse
    if all(f.type in SCALARS for f in fields):
        return None
    body, args, looked = [], [], []
    for i, f in enumerate(fields):
        if f.type in SCALARS:
            args.append(f"node.{f.name}")
        elif f.type == "Loc":
            args.append(f"new_loc((path, line, node.{f.name}[2] + shift))")
        else:  # another node, a tuple or a value of any type: its own relocator decides
            look = [f"g = R[type(v{i})]", f"a{i} = v{i} if g is None else g(v{i}, path, line, shift)"]
            if f.type.startswith("tuple["):  # an empty one (a selector without options) kept without a look
                look = [f"if v{i} is EMPTY:", f"    a{i} = v{i}", "else:", *(f"    {s}" for s in look)]
            body += [f"    v{i} = node.{f.name}", *(f"    {s}" for s in look)]
            args.append(f"a{i}")
            looked.append(i)
    if len(looked) == len(fields):  # no location of its own: the node itself when nothing inside moved
        body += ["    if " + " and ".join(f"a{i} is v{i}" for i in looked) + ":", "        return node"]
    if cls.new is cls:
        body.append(f"    return cls({', '.join(args)})")
    else:  # cls.new written out here (see frozen_init): a call less per node
        body += [*build_lines(cls, args), "    return self"]
    source = "def relocate(node, path, line, shift):\n" + "\n".join(body)
    namespace = {"R": _RELOCATORS, "cls": cls, "B": builder(cls), "_new": object.__new__, "new_loc": new_loc,
                 "EMPTY": ()}
    exec(source, namespace)  # noqa: S102  (the source is built from the field names above)
    return namespace["relocate"]


class _Relocators(dict):
    """type -> its relocator: None for an immutable value kept as it is, decided on first sight."""

    def __missing__(self, cls: type):
        if cls is Loc:
            relocator = _loc
        elif cls is tuple:
            relocator = _tuple
        elif issubclass(cls, _IMMUTABLE) and not issubclass(cls, (dict, list)):
            relocator = None
        elif is_frozen(cls):
            relocator = _dataclass_relocator(cls)
        else:
            relocator = _refuse
        self[cls] = relocator
        return relocator


_RELOCATORS = _Relocators()
ON_GUARD.append(lambda on: _RELOCATORS.clear())  # the code written for the other way of building
