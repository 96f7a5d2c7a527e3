"""``pack.mcmeta``: the formats a pack supports, its description and its overlays.

Fields (minecraft.wiki "Pack.mcmeta"):
- ``pack.pack_format`` int; required before 1.21.9, optional from 1.21.9 (25w31a) when
  ``min_format`` and ``max_format`` are given.
- ``pack.supported_formats`` (1.20.2 - 1.21.8): ``42``, ``[42, 45]`` or
  ``{"min_inclusive": 42, "max_inclusive": 45}``; must include ``pack_format``.
- ``pack.min_format`` / ``pack.max_format`` (1.21.9+): ``88`` or ``[88]`` or ``[88, 0]``.
  A single number as ``max_format`` means any minor version.
- ``overlays.entries``: ``{"directory": "[a-z0-9_-]+", "formats": RANGE}`` (or min/max_format);
  "the first in the list is applied first", so later entries win.
- ``filter.block``: ``[{"namespace": REGEX, "path": REGEX}]`` (1.19+), files of packs loaded
  *before* this one that match are treated as absent. As in the game's
  ``ResourceFilterSection``, a file is blocked when some pattern's namespace matches its
  namespace and some pattern's path matches its path inside the namespace
  (``function/a.mcfunction``); a missing regex matches everything; matches are whole-string.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from mcfunction_parser.diagnostics import ERROR, WARNING, Diagnostic
from mcfunction_parser.pack.text import JsonDocument, PackPath, load_json
from mcfunction_parser.pack.versions import Format

ANY_MINOR = 2**31 - 1
_OVERLAY_DIRECTORY = re.compile(r"[a-z0-9_-]+")


@dataclass(frozen=True)
class FormatRange:
    """Inclusive range of data pack formats."""

    min: Format
    max: Format

    def __contains__(self, fmt: Format) -> bool:
        return self.min <= fmt <= self.max


@dataclass(frozen=True)
class Overlay:
    directory: str
    formats: FormatRange


@dataclass(frozen=True)
class BlockFilter:
    """``filter.block``: patterns as (namespace regex, path regex); None matches everything."""

    patterns: tuple[tuple[re.Pattern | None, re.Pattern | None], ...]

    def blocks(self, namespace: str, path: str) -> bool:
        return (any(ns is None or ns.fullmatch(namespace) for ns, _ in self.patterns)
                and any(p is None or p.fullmatch(path) for _, p in self.patterns))


@dataclass
class PackMeta:
    pack_format: int | None
    supported: FormatRange | None
    description: str
    overlays: list[Overlay] = field(default_factory=list)
    block: BlockFilter | None = None


class _Invalid(Exception):
    """A malformed field: message and the offset of the token to point at."""

    def __init__(self, message: str, offset: int):
        super().__init__(message)
        self.offset = offset


def read_pack_meta(root: PackPath, shown_root: str, diagnostics: list[Diagnostic]) -> PackMeta | None:
    """Parse ``root/pack.mcmeta``; None (with an error) when it is missing or unusable."""
    path = root / "pack.mcmeta"
    shown = _join(shown_root, "pack.mcmeta")
    if not path.is_file():
        nested = sorted(child.name for child in root.iterdir()
                        if child.is_dir() and (child / "pack.mcmeta").is_file())
        hint = f" (found one inside {', '.join(repr(n + '/') for n in nested[:3])}: check that " \
            "folder instead)" if nested else ""
        diagnostics.append(Diagnostic(
            ERROR, f"missing pack.mcmeta: the game does not recognise this as a data pack{hint}",
            shown))
        return None
    doc = load_json(path, shown, diagnostics)
    if doc is None:
        return None
    notes: list[_Invalid] = []
    try:
        meta = _meta_from_json(doc, notes)
    except _Invalid as exc:
        diagnostics.append(doc.diagnostic(ERROR, f"invalid pack.mcmeta: {exc}", exc.offset))
        return None
    diagnostics.extend(doc.diagnostic(WARNING, f"pack.mcmeta: {note}", note.offset) for note in notes)
    return meta


def _join(root: str, name: str) -> str:
    return name if root in ("", ".") else f"{root.rstrip('/')}/{name}"


def _meta_from_json(doc: JsonDocument, notes: list[_Invalid]) -> PackMeta:
    """The metadata; ``notes`` collects what the game reads differently from how it is written."""
    root = doc.value
    if not isinstance(root, dict) or not isinstance(root.get("pack"), dict):
        raise _Invalid('expected an object with a "pack" object', doc.find_string("pack"))
    pack = root["pack"]
    reader = _Ints(doc, notes)
    pack_format = _pack_format(pack, doc, reader)
    supported = _supported_range(pack, pack_format, doc, reader)
    overlays = _overlays(root.get("overlays"), doc, reader)
    block = _block_filter(root.get("filter"), doc)
    return PackMeta(pack_format, supported, _plain_text(pack.get("description", "")), overlays, block)


class _Ints:
    """The format numbers as the game reads them: Codec.INT takes any JSON number
    (DataFixerUpper's JsonOps.getNumberValue) and keeps ``Number.intValue()`` of it, so Gson's
    LazilyParsedNumber truncates a decimal toward zero (``101.1`` is format 101, minor 0) and keeps
    the low 32 bits of a whole number. Such a number is a note: the author most likely meant
    ``[101, 1]``."""

    def __init__(self, doc: JsonDocument, notes: list[_Invalid]):
        self.doc = doc
        self.notes = notes

    def read(self, value: Any, key: str) -> int | None:
        """``value`` as the game's int, or None when it is no JSON number."""
        if isinstance(value, bool) or not isinstance(value, (int, float)) or value != value \
                or value in (float("inf"), float("-inf")):
            return None
        number = (int(value) + 2**31) % 2**32 - 2**31
        if number != value:
            self.notes.append(_Invalid(f'"{key}" {value!r} is read as {number} (the game keeps the whole '
                                       f'int part of a number; a minor version is written [major, minor])',
                                       self.doc.find_string(key)))
        return number

    def all(self, values: list, key: str) -> list[int] | None:
        numbers = [self.read(v, key) for v in values]
        return None if None in numbers else numbers


def _pack_format(pack: dict, doc: JsonDocument, ints: _Ints) -> int | None:
    value = pack.get("pack_format")
    if value is None:
        if "min_format" in pack and "max_format" in pack:
            return None
        raise _Invalid('"pack.pack_format" is missing (or give "min_format" and "max_format", '
                       '1.21.9+)', doc.find_string("pack"))
    number = ints.read(value, "pack_format")
    if number is None:
        raise _Invalid(f'"pack_format" must be an integer, not {_json_type(value)}',
                       doc.find_string("pack_format"))
    return number


def _supported_range(pack: dict, pack_format: int | None, doc: JsonDocument, ints: _Ints) -> FormatRange | None:
    if "min_format" in pack or "max_format" in pack:
        lo = _format_bound(pack.get("min_format"), "min_format", 0, doc, ints)
        hi = _format_bound(pack.get("max_format"), "max_format", ANY_MINOR, doc, ints)
        result = FormatRange(lo, hi)
    elif "supported_formats" in pack:
        result = _int_range(pack["supported_formats"], "supported_formats", doc, ints)
    elif pack_format is not None:
        return FormatRange((pack_format, 0), (pack_format, ANY_MINOR))
    else:
        return None
    if result.min > result.max:
        raise _Invalid("the supported range is empty (minimum above maximum)", doc.find_string("pack"))
    if pack_format is not None and not result.min[0] <= pack_format <= result.max[0]:
        raise _Invalid(f"the supported formats do not include pack_format {pack_format}",
                       doc.find_string("pack_format"))
    return result


def _format_bound(value: Any, key: str, default_minor: int, doc: JsonDocument, ints: _Ints) -> Format:
    """``88``, ``[88]`` or ``[88, 0]``; a bare major takes ``default_minor``."""
    number = None if isinstance(value, list) else ints.read(value, key)
    if number is not None:
        return (number, default_minor)
    numbers = ints.all(value, key) if isinstance(value, list) and len(value) in (1, 2) else None
    if numbers is not None:
        return (numbers[0], numbers[1] if len(numbers) == 2 else 0)
    raise _Invalid(f'"{key}" must be an integer or [major, minor]', doc.find_string(key))


def _int_range(value: Any, key: str, doc: JsonDocument, ints: _Ints) -> FormatRange:
    """``42``, ``[42, 45]`` or ``{"min_inclusive": 42, "max_inclusive": 45}`` (whole majors)."""
    if isinstance(value, list):
        bounds = ints.all(value, key) if len(value) == 2 else None
    elif isinstance(value, dict):
        bounds = ints.all([value.get(k) for k in ("min_inclusive", "max_inclusive")], key)
    else:
        single = ints.read(value, key)
        bounds = None if single is None else [single, single]
    if bounds is not None:
        lo, hi = bounds
    else:
        raise _Invalid(f'"{key}" must be an integer, [min, max] or '
                       '{"min_inclusive": N, "max_inclusive": N}', doc.find_string(key))
    return FormatRange((lo, 0), (hi, ANY_MINOR))


def _overlays(section: Any, doc: JsonDocument, ints: _Ints) -> list[Overlay]:
    if section is None:
        return []
    entries = section.get("entries") if isinstance(section, dict) else None
    if not isinstance(entries, list):
        raise _Invalid('"overlays" must be an object with an "entries" list', doc.find_string("overlays"))
    result = []
    after = doc.find_string("entries")
    for entry in entries:
        directory = entry.get("directory") if isinstance(entry, dict) else None
        offset = doc.find_string(directory, after) if isinstance(directory, str) else after
        if not isinstance(directory, str) or not _OVERLAY_DIRECTORY.fullmatch(directory):
            raise _Invalid('each overlay needs a "directory" made of a-z, 0-9, _ and -', offset)
        if "formats" in entry:
            formats = _int_range(entry["formats"], "formats", doc, ints)
        elif "min_format" in entry and "max_format" in entry:
            formats = FormatRange(_format_bound(entry["min_format"], "min_format", 0, doc, ints),
                                  _format_bound(entry["max_format"], "max_format", ANY_MINOR, doc, ints))
        else:
            raise _Invalid(f'overlay "{directory}" needs "formats" (or "min_format" and "max_format")',
                           offset)
        result.append(Overlay(directory, formats))
        after = max(after, offset)
    return result


def _block_filter(section: Any, doc: JsonDocument) -> BlockFilter | None:
    if section is None:
        return None
    block = section.get("block") if isinstance(section, dict) else None
    if not isinstance(block, list) or not all(isinstance(p, dict) for p in block):
        raise _Invalid('"filter" must be an object with a "block" list of objects', doc.find_string("filter"))
    patterns = tuple((_regex(p, "namespace", doc), _regex(p, "path", doc)) for p in block)
    return BlockFilter(patterns)


def _regex(pattern: dict, key: str, doc: JsonDocument) -> re.Pattern | None:
    text = pattern.get(key)
    if text is None:
        return None
    if not isinstance(text, str):
        raise _Invalid(f'filter "{key}" must be a regular expression string', doc.find_string(key))
    try:
        return re.compile(text)
    except re.error as exc:
        raise _Invalid(f'filter "{key}" is not a valid regular expression: {exc}',
                       doc.find_string(text)) from None


def _plain_text(component: Any) -> str:
    """The visible text of a JSON text component (string, list, or object with text/extra)."""
    if isinstance(component, str):
        return component
    if isinstance(component, list):
        return "".join(_plain_text(part) for part in component)
    if isinstance(component, dict):
        own = component.get("text", component.get("translate", ""))
        extra = component.get("extra")
        return _plain_text(own) + (_plain_text(extra) if isinstance(extra, list) else "")
    if isinstance(component, bool):
        return "true" if component else "false"
    return "" if component is None else str(component)


def _json_type(value: Any) -> str:
    return {str: "a string", float: "a decimal number", list: "a list", dict: "an object",
            bool: "a boolean"}.get(type(value), "null")
