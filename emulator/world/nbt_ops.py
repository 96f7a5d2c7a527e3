"""NBT paths and ``data`` operations on :mod:`mcfunction_parser.nbt` values, as the game does them.

Tags are the parser's NBT classes (``Compound`` dict, ``List`` list, ``Int``, ``Float`` ...).
Operations mutate the root compound in place, like the game's storage accessor does; a caller
that must not see partial changes on failure (the entity accessor) passes a copy and keeps it only
on success. Failures raise :class:`emulator.world.errors.CommandFailure` with the game's message.

Public functions
- ``tags_equal(a, b)``: ``Tag.equals`` (type-strict: ``1b`` differs from ``1``; float ``==``).
- ``copy_tag(tag)``: a deep copy keeping tag classes.
- ``compare_nbt(pattern, actual, partial_lists=True)``: ``NbtUtils.compareNbt``, the partial match
  used by ``nbt=`` in selectors and by ``{...}`` / ``[{...}]`` path filters.
- ``get(root, path)``: every match (list); fails "Found no elements matching <prefix>".
- ``count_matching(root, path)``: ``execute if data`` (0 when nothing matches, never fails).
- ``set_path(root, path, value)``: ``data modify ... set`` / ``execute store``: creates missing
  compounds and lists; returns how many tags changed.
- ``insert(root, path, index, values)``: ``append`` (index -1), ``prepend`` (0), ``insert I``.
- ``merge_into(root, path, values)``: ``data modify ... merge``.
- ``remove(root, path)``: ``data remove`` (count removed; never fails by itself).
- ``modify(root, path, mode, values, index=None)``: the whole ``data modify`` step, failing with
  "Nothing changed" when the count is 0 (``set`` uses the last source value).
- ``data_remove(root, path)``: ``data remove`` with its "Nothing changed" failure.
- ``data_merge(root, patch)``: ``data merge`` in place (returns 1) or fails "Nothing changed".
- ``merge_compounds(target, patch)``: ``CompoundTag.merge`` (recursive into compounds) in place.
- ``string_source(values, start=None, end=None)``: the ``string`` source of ``data modify``.
- ``list_rules(version)``: a context manager selecting the list rule of a game version: one tag
  type per list before 1.21.5, mixed types allowed from 1.21.5 (default: the older rule).
- ``numeric_value(tag)``: ``NumericTag.getAsDouble``; ``narrow(tag, Byte|Short|Int|Long)``:
  ``getAsByte/Short/Int/Long``; ``is_numeric(tag)``.
- ``snbt(tag)`` / ``tag_as_string(tag)``: ``Tag.toString`` / ``Tag.getAsString`` as the game prints
  them under the release in force (StringTagVisitor: sorted keys, Java floats, 1.21.5's quoting).

A path is an :class:`mcfunction_parser.ast.NbtPath` (``nodes`` and ``text``).
Source: decompiled 1.21 ``commands/arguments/NbtPathArgument.java``, ``nbt/NbtUtils.java``,
``nbt/ListTag.java``, ``nbt/CompoundTag.java``, ``server/commands/data/DataCommands.java``.
"""
from __future__ import annotations

import math
from abc import ABC, abstractmethod
from contextvars import ContextVar

from mcfunction_parser import ast
from mcfunction_parser.nbt import (
    ARRAY_TYPES,
    Byte,
    Compound,
    Double,
    Float,
    INT_RANGES as INT_BITS,
    Int,
    List,
    Long,
    Short,
    NUMERIC_TYPES,
    String,
    to_snbt,
    type_of_array_item,
)
from emulator.world.semantics import double_to_long, mth_floor
from emulator.world import mth
from emulator.world.errors import CommandFailure
from emulator.world.text import java_double_string, java_float_string

MAX_DEPTH = 512

# ----------------------------------------------------------------------------- tags


def is_numeric(tag) -> bool:
    return isinstance(tag, NUMERIC_TYPES)


def is_collection(tag) -> bool:
    """``CollectionTag``: lists and the three array types."""
    return isinstance(tag, (List,) + ARRAY_TYPES)


def numeric_value(tag) -> float:
    """``NumericTag.getAsDouble()``: a float tag widens its float32 value."""
    if isinstance(tag, Float):
        return float(mth.f32(float(tag)))
    return float(tag)


# The recursive helpers below use plain loops (one frame per level) so that NBT nested to the
# game's limit of 512 levels stays within Python's default recursion limit.


def int_at(compound, key: str, default: int = 0) -> int:
    """The number under ``key`` as an int (CompoundTag.getInt and kin), ``default`` when no number is there."""
    value = compound.get(key)
    return int(numeric_value(value)) if is_numeric(value) else default


def tags_equal(a, b) -> bool:
    """``Tag.equals``: same tag type and equal content (floats compare with ``==``, so NaN != NaN)."""
    kind = type(a)
    if kind is not type(b):
        return False
    if kind in _LEAF_TAGS:  # the common case first: a number or a string
        return a == b
    if isinstance(a, dict):
        if a.keys() != b.keys():
            return False
        for key, value in a.items():
            if not tags_equal(value, b[key]):
                return False
        return True
    if isinstance(a, list) and kind not in ARRAY_TYPES:
        if len(a) != len(b):
            return False
        if not a:  # an empty inventory: no zip to make
            return True
        for x, y in zip(a, b):
            if not tags_equal(x, y):
                return False
        return True
    return a == b


_LEAF_TAGS = frozenset({Byte, Short, Int, Long, Float, Double, String})


def copy_tag(tag):
    """A deep copy that keeps every tag class."""
    if isinstance(tag, dict):
        copy = type(tag)()
        for key, value in tag.items():
            copy[key] = copy_tag(value)
        return copy
    if isinstance(tag, list):
        copy = type(tag)()
        for value in tag:
            copy.append(copy_tag(value))
        return copy
    return tag


def compare_nbt(pattern, actual, partial_lists: bool = True) -> bool:
    """``NbtUtils.compareNbt``: every key of a pattern compound must match; with ``partial_lists``
    each element of a pattern list must match some element of the actual list (an empty pattern
    list only matches an empty list, and the actual list must be at least as long)."""
    if pattern is None:
        return True
    if actual is None or type(pattern) is not type(actual):
        return False
    if isinstance(pattern, dict):
        if len(actual) < len(pattern):
            return False
        for key, value in pattern.items():
            if not compare_nbt(value, actual.get(key), partial_lists):
                return False
        return True
    if isinstance(pattern, List) and partial_lists:
        if not pattern:
            return not actual
        if len(actual) < len(pattern):
            return False
        for wanted in pattern:
            for candidate in actual:
                if compare_nbt(wanted, candidate, partial_lists):
                    break
            else:
                return False
        return True
    return tags_equal(pattern, actual)


def is_too_deep(tag, depth: int) -> bool:
    """``NbtPath.isTooDeep``: nesting of 512 levels or more (counting the path's own depth)."""
    pending = [(tag, depth)]
    while pending:
        tag, depth = pending.pop()
        if depth >= MAX_DEPTH:
            return True
        if isinstance(tag, dict):
            pending.extend((v, depth + 1) for v in tag.values())
        elif isinstance(tag, List):
            pending.extend((v, depth + 1) for v in tag)
    return False


def merge_compounds(target: Compound, patch: Compound) -> Compound:
    """``CompoundTag.merge``: compounds merge recursively into compounds, anything else replaces."""
    for key, value in patch.items():
        if isinstance(value, Compound) and isinstance(target.get(key), Compound):
            merge_compounds(target[key], value)
        else:
            target[key] = copy_tag(value)
    return target


# ----------------------------------------------------------------------------- collections


def _array_item(array, tag):
    """The value an array stores for a numeric tag (``getAsByte``/``getAsInt``/``getAsLong``)."""
    return type_of_array_item(array)(narrow(tag, type_of_array_item(array)))


def narrow(tag, target: type) -> int:
    """``NumericTag.getAsByte/Short/Int/Long``: integers keep their low bits; a float or double goes
    through ``Mth.floor`` (``getAsLong``: ``(long) f`` for floats, ``(long) Math.floor(d)`` for doubles)."""
    if isinstance(tag, (Float, Double)):
        value = numeric_value(tag)
        if target is Long:
            return double_to_long(value if isinstance(tag, Float) or not math.isfinite(value) else math.floor(value))
        whole = mth_floor(value)
    else:
        whole = int(tag)
    half = 1 << (INT_BITS[target] - 1)
    return ((whole + half) & ((1 << INT_BITS[target]) - 1)) - half


def _element_tag(collection, index: int):
    """``CollectionTag.get(i)``: arrays hand out tags of their item type."""
    item = collection[index]
    return _array_item(collection, item) if isinstance(collection, ARRAY_TYPES) else item


def _elements(collection) -> list:
    return [_element_tag(collection, i) for i in range(len(collection))]


# Up to 1.21.4 a list holds one tag type; from 1.21.5 a list may mix types. Operations read the
# rule of the pack being run from this context variable (see ``list_rules``).
_MIXED_LISTS: ContextVar[bool] = ContextVar("mixed_lists", default=False)
MIXED_LISTS_VERSION = (1, 21, 5)


class list_rules:
    """Run NBT operations with the list rule of ``version`` (mixed-type lists from 1.21.5): a
    context manager (a class: every root sequence enters one). Entering the rule in force already
    changes nothing (a root inside a tick, the older rule outside any)."""

    __slots__ = ("mixed", "token")

    def __init__(self, version: tuple[int, int, int]) -> None:
        self.mixed = tuple(version) >= MIXED_LISTS_VERSION

    def __enter__(self) -> None:
        self.token = None if _MIXED_LISTS.get() is self.mixed else _MIXED_LISTS.set(self.mixed)

    def __exit__(self, *exc) -> None:
        if self.token is not None:
            _MIXED_LISTS.reset(self.token)


# whether the list rule in force lets a list mix tag types (:class:`list_rules`); the context
# variable's own method: the runtime asks each tick
lists_mixed = _MIXED_LISTS.get


def snbt(tag) -> str:
    """The tag as the game prints it (Tag.toString, StringTagVisitor) under the release in force:
    floats and doubles as Java writes them, and the 1.21.5 SNBT that lets lists mix types also quotes
    keys its own way (:func:`to_snbt`)."""
    return to_snbt(tag, _MIXED_LISTS.get(), _java_decimal)


def _java_decimal(tag) -> str:
    """StringTagVisitor.visitFloat / visitDouble: Float.toString, Double.toString."""
    return java_float_string(float(tag)) if isinstance(tag, Float) else java_double_string(float(tag))


def tag_as_string(tag) -> str:
    """``Tag.getAsString()``: a string's own text, anything else as SNBT (a number with its suffix:
    ``1b``, ``2.5f``, ``0.1d``, ``3L``). It is what ``data modify ... string`` copies, what ``data
    get`` shows for a single value and what a text component's ``nbt`` shows."""
    return str(tag) if isinstance(tag, str) else snbt(tag)


def _list_accepts(lst: List, tag) -> bool:
    """``ListTag.updateType`` (before 1.21.5): a list holds one tag type, fixed by its first element."""
    return _MIXED_LISTS.get() or not lst or type(lst[0]) is type(tag)


def _add_tag(collection, index: int, tag) -> bool:
    """``CollectionTag.addTag``: False for a wrong type; IndexError for a bad index."""
    if isinstance(collection, ARRAY_TYPES):
        if not is_numeric(tag):
            return False
        stored = _array_item(collection, tag)
    else:
        if not _list_accepts(collection, tag):
            return False
        stored = tag
    if not 0 <= index <= len(collection):
        raise IndexError(index)
    collection.insert(index, stored)
    return True


def _set_tag(collection, index: int, tag) -> bool:
    """``CollectionTag.setTag``: replace one element if the type fits."""
    if isinstance(collection, ARRAY_TYPES):
        if not is_numeric(tag):
            return False
        collection[index] = _array_item(collection, tag)
        return True
    if not _list_accepts(collection, tag):
        return False
    collection[index] = tag
    return True


# ----------------------------------------------------------------------------- path nodes


class _Node(ABC):
    """One game path node (``NbtPathArgument.Node``); ``end`` is where it ends in the path text."""

    end: int = 0

    @abstractmethod
    def get(self, tag) -> list:
        """The tags this node selects under ``tag``."""

    def get_or_create(self, tag, make) -> list:
        """Like ``get``, creating what is missing with ``make()`` where the node can."""
        return self.get(tag)

    def preferred_parent(self):
        """The container a missing parent of this node is created as."""
        return List()

    @abstractmethod
    def set(self, tag, value) -> int:
        """Replace what this node selects under ``tag`` with ``value()``; how many changed."""

    @abstractmethod
    def remove(self, tag) -> int:
        """Remove what this node selects under ``tag``; how many were removed."""


class _Child(_Node):
    def __init__(self, name: str) -> None:
        self.name = name

    def get(self, tag) -> list:
        return [tag[self.name]] if isinstance(tag, Compound) and self.name in tag else []

    def get_or_create(self, tag, make) -> list:
        if not isinstance(tag, Compound):
            return []
        if self.name not in tag:
            tag[self.name] = make()
        return [tag[self.name]]

    def preferred_parent(self):
        return Compound()

    def set(self, tag, value) -> int:
        if not isinstance(tag, Compound):
            return 0
        previous = tag.get(self.name)
        tag[self.name] = value()
        return 0 if previous is not None and tags_equal(tag[self.name], previous) else 1

    def remove(self, tag) -> int:
        if isinstance(tag, Compound) and self.name in tag:
            del tag[self.name]
            return 1
        return 0


class _MatchChild(_Node):
    """``key{pattern}``: the child only if it matches the pattern; created as the pattern."""

    def __init__(self, name: str, pattern: Compound) -> None:
        self.name = name
        self.pattern = pattern

    def _matching(self, tag):
        if not isinstance(tag, Compound):
            return None
        child = tag.get(self.name)
        return child if compare_nbt(self.pattern, child) else None

    def get(self, tag) -> list:
        child = self._matching(tag)
        return [] if child is None else [child]

    def get_or_create(self, tag, make) -> list:
        if isinstance(tag, Compound) and self.name not in tag:
            tag[self.name] = copy_tag(self.pattern)
            return [tag[self.name]]
        return self.get(tag)

    def preferred_parent(self):
        return Compound()

    def set(self, tag, value) -> int:
        child = self._matching(tag)
        if child is None:
            return 0
        new = value()
        if tags_equal(new, child):
            return 0
        tag[self.name] = new
        return 1

    def remove(self, tag) -> int:
        if self._matching(tag) is None:
            return 0
        del tag[self.name]
        return 1


class _MatchRoot(_Node):
    """``{pattern}`` as the first node: the root itself if it matches; never set or removed."""

    def __init__(self, pattern: Compound) -> None:
        self.pattern = pattern

    def get(self, tag) -> list:
        return [tag] if isinstance(tag, Compound) and compare_nbt(self.pattern, tag) else []

    def preferred_parent(self):
        return Compound()

    def set(self, tag, value) -> int:
        return 0

    def remove(self, tag) -> int:
        return 0


class _Index(_Node):
    def __init__(self, index: int) -> None:
        self.index = index

    def _resolve(self, tag):
        if not is_collection(tag):
            return None
        i = len(tag) + self.index if self.index < 0 else self.index
        return i if 0 <= i < len(tag) else None

    def get(self, tag) -> list:
        i = self._resolve(tag)
        return [] if i is None else [_element_tag(tag, i)]

    def set(self, tag, value) -> int:
        i = self._resolve(tag)
        if i is None:
            return 0
        new = value()
        return 1 if not tags_equal(new, _element_tag(tag, i)) and _set_tag(tag, i, new) else 0

    def remove(self, tag) -> int:
        i = self._resolve(tag)
        if i is None:
            return 0
        del tag[i]
        return 1


class _All(_Node):
    """``[]``: every element of a list or array."""

    def get(self, tag) -> list:
        return _elements(tag) if is_collection(tag) else []

    def get_or_create(self, tag, make) -> list:
        if not is_collection(tag):
            return []
        if tag:
            return _elements(tag)
        new = make()
        return [new] if _add_tag(tag, 0, new) else []

    def set(self, tag, value) -> int:
        if not is_collection(tag):
            return 0
        size = len(tag)
        if size == 0:
            _add_tag(tag, 0, value())  # the game counts 1 even if the add was refused
            return 1
        first = value()
        changed = sum(1 for e in _elements(tag) if not tags_equal(first, e))
        if changed == 0:
            return 0
        del tag[:]
        if not _add_tag(tag, 0, first):
            return 0
        for k in range(1, size):
            _add_tag(tag, k, value())
        return changed

    def remove(self, tag) -> int:
        if is_collection(tag) and tag:
            size = len(tag)
            del tag[:]
            return size
        return 0


class _MatchElement(_Node):
    """``[{pattern}]``: every compound element of a list matching the pattern."""

    def __init__(self, pattern: Compound) -> None:
        self.pattern = pattern

    def get(self, tag) -> list:
        return [e for e in tag if compare_nbt(self.pattern, e)] if isinstance(tag, List) else []

    def get_or_create(self, tag, make) -> list:
        if not isinstance(tag, List):
            return []
        found = self.get(tag)
        if found:
            return found
        created = copy_tag(self.pattern)
        if not _list_accepts(tag, created):
            return []
        tag.append(created)
        return [created]

    def set(self, tag, value) -> int:
        if not isinstance(tag, List):
            return 0
        if not tag:
            tag.append(value())
            return 1
        changed = 0
        for k in range(len(tag)):
            if compare_nbt(self.pattern, tag[k]):
                new = value()
                if not tags_equal(new, tag[k]) and _set_tag(tag, k, new):
                    changed += 1
        return changed

    def remove(self, tag) -> int:
        if not isinstance(tag, List):
            return 0
        removed = 0
        for k in range(len(tag) - 1, -1, -1):
            if compare_nbt(self.pattern, tag[k]):
                del tag[k]
                removed += 1
        return removed


# ----------------------------------------------------------------------------- compiling paths


def _compile(path: ast.NbtPath) -> list[_Node]:
    """AST path nodes to game nodes: ``PathKey`` + ``PathFilter`` is one ``key{...}`` node."""
    nodes: list[_Node] = []
    for position, node in enumerate(path.nodes):
        if isinstance(node, ast.PathKey):
            nodes.append(_Child(node.name))
        elif isinstance(node, ast.PathFilter):
            if position == 0:
                nodes.append(_MatchRoot(node.pattern))
            elif isinstance(nodes[-1], _Child) and not isinstance(nodes[-1], _MatchChild):
                nodes[-1] = _MatchChild(nodes[-1].name, node.pattern)
            else:
                raise CommandFailure("arguments.nbtpath.node.invalid")
        elif isinstance(node, ast.PathIndex):
            nodes.append(_Index(node.index))
        elif isinstance(node, ast.PathAll):
            nodes.append(_All())
        elif isinstance(node, ast.PathMatch):
            nodes.append(_MatchElement(node.pattern))
        else:
            raise CommandFailure("arguments.nbtpath.node.invalid")
    ends = _node_ends(path.text)
    for node, end in zip(nodes, ends if len(ends) == len(nodes) else [len(path.text)] * len(nodes)):
        node.end = end
    return nodes


def _skip_quoted(text: str, i: int) -> int:
    quote = text[i]
    i += 1
    while i < len(text) and text[i] != quote:
        i += 2 if text[i] == "\\" else 1
    return i + 1


def _skip_balanced(text: str, i: int) -> int:
    """From an opening ``{`` or ``[`` to just past its partner, skipping quoted strings."""
    depth = 0
    while i < len(text):
        c = text[i]
        if c in "\"'":
            i = _skip_quoted(text, i)
            continue
        if c in "{[":
            depth += 1
        elif c in "}]":
            depth -= 1
            if depth == 0:
                return i + 1
        i += 1
    return i


def _node_ends(text: str) -> list[int]:
    """Where each game node ends in the path text, to quote the prefix as the game does."""
    ends, i = [], 0
    while i < len(text) and text[i] != " ":
        c = text[i]
        if c in "\"'":
            i = _skip_quoted(text, i)
        elif c in "[{":
            i = _skip_balanced(text, i)
        else:
            while i < len(text) and text[i] not in " \"'[].{}":
                i += 1
        if c not in "[{" and i < len(text) and text[i] == "{":
            i = _skip_balanced(text, i)
        ends.append(i)
        if i < len(text) and text[i] == ".":
            i += 1
    return ends


def _nothing_found(path: ast.NbtPath, node: _Node) -> CommandFailure:
    return CommandFailure("arguments.nbtpath.nothing_found", path.text[: node.end])


# ----------------------------------------------------------------------------- path operations


def get(root, path: ast.NbtPath) -> list:
    """Every tag the path selects; fails when a step selects nothing."""
    found = [root]
    for node in _compile(path):
        found = [t for parent in found for t in node.get(parent)]
        if not found:
            raise _nothing_found(path, node)
    return found


def count_matching(root, path: ast.NbtPath) -> int:
    """``execute if data``: how many tags the path selects (0, never a failure)."""
    found = [root]
    for node in _compile(path):
        found = [t for parent in found for t in node.get(parent)]
        if not found:
            return 0
    return len(found)


def _parents(root, path: ast.NbtPath, nodes: list[_Node]) -> list:
    found = [root]
    for node, following in zip(nodes, nodes[1:]):
        found = [t for parent in found for t in node.get_or_create(parent, following.preferred_parent)]
        if not found:
            raise _nothing_found(path, node)
    return found


def _get_or_create(root, path: ast.NbtPath, nodes: list[_Node], make) -> list:
    return [t for parent in _parents(root, path, nodes) for t in nodes[-1].get_or_create(parent, make)]


def set_path(root, path: ast.NbtPath, value) -> int:
    """Set every tag the path selects to a copy of ``value``; returns how many changed."""
    nodes = _compile(path)
    if is_too_deep(value, len(nodes)):
        raise CommandFailure("arguments.nbtpath.too_deep")
    return sum(nodes[-1].set(parent, lambda: copy_tag(value)) for parent in _parents(root, path, nodes))


def insert(root, path: ast.NbtPath, index: int, values: list) -> int:
    """Insert copies of ``values`` at ``index`` (negative counts from the end, -1 appends) into every
    list the path selects (created if missing); returns how many lists changed."""
    nodes = _compile(path)
    copies = [copy_tag(v) for v in values]
    if any(is_too_deep(v, len(nodes)) for v in copies):
        raise CommandFailure("arguments.nbtpath.too_deep")
    changed = 0
    for target in _get_or_create(root, path, nodes, List):
        if not is_collection(target):
            raise CommandFailure("commands.data.modify.expected_list", snbt(target))
        position = len(target) + index + 1 if index < 0 else index
        added = False
        for value in copies:
            try:
                if _add_tag(target, position, copy_tag(value)):
                    position += 1
                    added = True
            except IndexError:
                raise CommandFailure("commands.data.modify.invalid_index", position) from None
        changed += added
    return changed


def merge_into(root, path: ast.NbtPath, values: list) -> int:
    """``data modify ... merge``: merge every source compound into every selected compound."""
    patch = Compound()
    for value in values:
        if is_too_deep(value, 0):
            raise CommandFailure("arguments.nbtpath.too_deep")
        if not isinstance(value, Compound):
            raise CommandFailure("commands.data.modify.expected_object", snbt(value))
        merge_compounds(patch, value)
    changed = 0
    for target in _get_or_create(root, path, _compile(path), Compound):
        if not isinstance(target, Compound):
            raise CommandFailure("commands.data.modify.expected_object", snbt(target))
        before = copy_tag(target)
        merge_compounds(target, patch)
        changed += not tags_equal(before, target)
    return changed


def remove(root, path: ast.NbtPath) -> int:
    """Remove every tag the path selects; returns the count (intermediate misses select nothing)."""
    nodes = _compile(path)
    found = [root]
    for node in nodes[:-1]:
        found = [t for parent in found for t in node.get(parent)]
    return sum(nodes[-1].remove(parent) for parent in found)


def _changed(count: int) -> int:
    if count == 0:
        raise CommandFailure("commands.data.merge.failed")
    return count


def modify(root, path: ast.NbtPath, mode: str, values: list, index: int | None = None) -> int:
    """One ``data modify`` with its source values already resolved; fails when nothing changed."""
    if mode == "set":
        return _changed(set_path(root, path, values[-1]))
    if mode == "merge":
        return _changed(merge_into(root, path, values))
    position = {"append": -1, "prepend": 0, "insert": index}[mode]
    return _changed(insert(root, path, position, values))


def data_remove(root, path: ast.NbtPath) -> int:
    return _changed(remove(root, path))


def data_merge(root: Compound, patch: Compound) -> int:
    """``data merge``: merge ``patch`` into ``root`` in place (returns 1); fails when nothing changes."""
    if is_too_deep(patch, 0):
        raise CommandFailure("arguments.nbtpath.too_deep")
    merged = merge_compounds(copy_tag(root), patch)
    if tags_equal(merged, root):
        raise CommandFailure("commands.data.merge.failed")
    root.clear()
    root.update(merged)
    return 1


def _as_text(tag) -> str:
    """``Tag.getAsString`` for value tags (strings and numbers); compounds and lists fail."""
    if isinstance(tag, str) or is_numeric(tag):
        return tag_as_string(tag)
    raise CommandFailure("commands.data.modify.expected_value", snbt(tag))


def string_source(values: list, start: int | None = None, end: int | None = None) -> list:
    """``data modify ... string SOURCE [PATH] [START] [END]``: each value as a String tag, sliced;
    negative bounds count from the end; bad bounds fail "Invalid substring indices"."""
    result = []
    for value in values:
        text = _as_text(value)
        if start is None:
            result.append(String(text))
            continue
        lo = start if start >= 0 else len(text) + start
        hi = len(text) if end is None else end if end >= 0 else len(text) + end
        if not (0 <= lo <= hi <= len(text)):
            raise CommandFailure("commands.data.modify.invalid_substring", lo, hi)
        result.append(String(text[lo:hi]))
    return result
