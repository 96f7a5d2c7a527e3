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

from mcfunction_parser.diagnostics import ERROR, Diagnostic
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
    try:
        return _meta_from_json(doc)
    except _Invalid as exc:
        diagnostics.append(doc.diagnostic(ERROR, f"invalid pack.mcmeta: {exc}", exc.offset))
        return None


def _join(root: str, name: str) -> str:
    return name if root in ("", ".") else f"{root.rstrip('/')}/{name}"


def _meta_from_json(doc: JsonDocument) -> PackMeta:
    root = doc.value
    if not isinstance(root, dict) or not isinstance(root.get("pack"), dict):
        raise _Invalid('expected an object with a "pack" object', doc.find_string("pack"))
    pack = root["pack"]
    pack_format = _pack_format(pack, doc)
    supported = _supported_range(pack, pack_format, doc)
    overlays = _overlays(root.get("overlays"), doc)
    block = _block_filter(root.get("filter"), doc)
    return PackMeta(pack_format, supported, _plain_text(pack.get("description", "")), overlays, block)


def _pack_format(pack: dict, doc: JsonDocument) -> int | None:
    value = pack.get("pack_format")
    if value is None:
        if "min_format" in pack and "max_format" in pack:
            return None
        raise _Invalid('"pack.pack_format" is missing (or give "min_format" and "max_format", '
                       '1.21.9+)', doc.find_string("pack"))
    if not _is_int(value):
        raise _Invalid(f'"pack_format" must be an integer, not {_json_type(value)}',
                       doc.find_string("pack_format"))
    return value


def _supported_range(pack: dict, pack_format: int | None, doc: JsonDocument) -> FormatRange | None:
    if "min_format" in pack or "max_format" in pack:
        lo = _format_bound(pack.get("min_format"), "min_format", 0, doc)
        hi = _format_bound(pack.get("max_format"), "max_format", ANY_MINOR, doc)
        result = FormatRange(lo, hi)
    elif "supported_formats" in pack:
        result = _int_range(pack["supported_formats"], "supported_formats", doc)
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


def _format_bound(value: Any, key: str, default_minor: int, doc: JsonDocument) -> Format:
    """``88``, ``[88]`` or ``[88, 0]``; a bare major takes ``default_minor``."""
    if _is_int(value):
        return (value, default_minor)
    if isinstance(value, list) and len(value) in (1, 2) and all(_is_int(v) for v in value):
        return (value[0], value[1] if len(value) == 2 else 0)
    raise _Invalid(f'"{key}" must be an integer or [major, minor]', doc.find_string(key))


def _int_range(value: Any, key: str, doc: JsonDocument) -> FormatRange:
    """``42``, ``[42, 45]`` or ``{"min_inclusive": 42, "max_inclusive": 45}`` (whole majors)."""
    if _is_int(value):
        lo = hi = value
    elif isinstance(value, list) and len(value) == 2 and all(_is_int(v) for v in value):
        lo, hi = value
    elif isinstance(value, dict) and all(_is_int(value.get(k)) for k in ("min_inclusive", "max_inclusive")):
        lo, hi = value["min_inclusive"], value["max_inclusive"]
    else:
        raise _Invalid(f'"{key}" must be an integer, [min, max] or '
                       '{"min_inclusive": N, "max_inclusive": N}', doc.find_string(key))
    return FormatRange((lo, 0), (hi, ANY_MINOR))


def _overlays(section: Any, doc: JsonDocument) -> list[Overlay]:
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
            formats = _int_range(entry["formats"], "formats", doc)
        elif "min_format" in entry and "max_format" in entry:
            formats = FormatRange(_format_bound(entry["min_format"], "min_format", 0, doc),
                                  _format_bound(entry["max_format"], "max_format", ANY_MINOR, doc))
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


def _is_int(value: Any) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def _json_type(value: Any) -> str:
    return {str: "a string", float: "a decimal number", list: "a list", dict: "an object",
            bool: "a boolean"}.get(type(value), "null")
