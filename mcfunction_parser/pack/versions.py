"""Game releases and the data pack formats they read.

A data pack format is ``(major, minor)``; before 1.21.9 every format was a plain integer, kept here
as ``(n, 0)``. Numbers from minecraft.wiki "Pack format" (data pack table) and "Pack.mcmeta";
1.21.9 introduced ``min_format``/``max_format`` and the minor part (1.21.9 reads 88.0, 1.21.11
reads 94.1).

After 1.21.11 releases are numbered by year and drop (26.1 is the first drop of 2026); a version
is still ``(major, minor, patch)``, so 26.1.2 is ``(26, 1, 2)`` and sorts after every 1.x release.
26.1 – 26.1.2 read 101.1 and 26.2 reads 107.1: the ``pack_version`` of the game jars'
version.json (26.1.2: data_major 101, data_minor 1, world version 4790; 26.2: data_major 107,
data_minor 1, world version 4903) as quoted by several independent projects, and "101.1 (26.1)"
in two data pack references; 26.1.1 lies between two releases reading 101.1 and formats never
decrease. 26.3 is not listed: no source at hand gives its release format.
"""
from __future__ import annotations

import re

Version = tuple[int, int, int]
Format = tuple[int, int]

# Data pack format -> the releases that read it, oldest first.
_FORMAT_RELEASES: tuple[tuple[Format, str], ...] = (
    ((4, 0), "1.13 1.13.1 1.13.2 1.14 1.14.1 1.14.2 1.14.3 1.14.4"),
    ((5, 0), "1.15 1.15.1 1.15.2 1.16 1.16.1"),
    ((6, 0), "1.16.2 1.16.3 1.16.4 1.16.5"),
    ((7, 0), "1.17 1.17.1"),
    ((8, 0), "1.18 1.18.1"),
    ((9, 0), "1.18.2"),
    ((10, 0), "1.19 1.19.1 1.19.2 1.19.3"),
    ((12, 0), "1.19.4"),
    ((15, 0), "1.20 1.20.1"),
    ((18, 0), "1.20.2"),
    ((26, 0), "1.20.3 1.20.4"),
    ((41, 0), "1.20.5 1.20.6"),
    ((48, 0), "1.21 1.21.1"),
    ((57, 0), "1.21.2 1.21.3"),
    ((61, 0), "1.21.4"),
    ((71, 0), "1.21.5"),
    ((80, 0), "1.21.6"),
    ((81, 0), "1.21.7 1.21.8"),
    ((88, 0), "1.21.9 1.21.10"),
    ((94, 1), "1.21.11"),
    ((101, 1), "26.1 26.1.1 26.1.2"),
    ((107, 1), "26.2"),
)

# First format whose packs keep functions in data/<ns>/function and tags/function (1.21).
SINGULAR_FOLDERS_FORMAT: Format = (48, 0)
# First formats whose games read pack.mcmeta "filter" (1.19, 22w11a) and "overlays" (1.20.2, 23w31a).
FILTER_FORMAT: Format = (10, 0)
OVERLAYS_FORMAT: Format = (18, 0)

_VERSION_RE = re.compile(r"(\d+)\.(\d+)(?:\.(\d+))?")


def parse_mc_version(text: str) -> Version:
    """``"1.21.4"`` -> ``(1, 21, 4)``; ``"1.21"`` -> ``(1, 21, 0)``. Raises ValueError if malformed."""
    match = _VERSION_RE.fullmatch(text.strip())
    if match is None:
        raise ValueError(f"'{text}' is not a game version (expected e.g. 1.21.4)")
    major, minor, patch = match.groups()
    return int(major), int(minor), int(patch or 0)


def version_label(version: Version) -> str:
    """``(1, 21, 0)`` -> ``"1.21"``; ``(1, 21, 4)`` -> ``"1.21.4"``."""
    major, minor, patch = version
    return f"{major}.{minor}" + (f".{patch}" if patch else "")


def format_label(fmt: Format) -> str:
    """``(61, 0)`` -> ``"61"``; ``(94, 1)`` -> ``"94.1"``."""
    return f"{fmt[0]}.{fmt[1]}" if fmt[1] else str(fmt[0])


def _build_release_table() -> dict[Version, Format]:
    table = {}
    for fmt, names in _FORMAT_RELEASES:
        for name in names.split():
            table[parse_mc_version(name)] = fmt
    return table


RELEASE_FORMATS: dict[Version, Format] = _build_release_table()
LATEST_RELEASE: Version = max(RELEASE_FORMATS)


def pack_format_for_version(version: Version) -> Format:
    """The data pack format a release reads. Raises ValueError for an unknown release."""
    try:
        return RELEASE_FORMATS[version]
    except KeyError:
        known = f"{version_label(min(RELEASE_FORMATS))} ... {version_label(LATEST_RELEASE)}"
        raise ValueError(f"unknown release {version_label(version)} (known: {known})") from None


def newer_than_known(fmt: int | Format) -> bool:
    """True when ``fmt`` is newer than the format of every known release (a pack made for a game
    this table does not know yet)."""
    wanted = (fmt, 0) if isinstance(fmt, int) else tuple(fmt)
    return wanted > RELEASE_FORMATS[LATEST_RELEASE]


def version_for_pack_format(fmt: int | Format) -> Version:
    """The newest release whose format is ``fmt`` or, for a snapshot-only format, the newest
    release with an older format; formats newer than every release map to the latest release."""
    wanted = (fmt, 0) if isinstance(fmt, int) else tuple(fmt)
    older = [v for v, f in RELEASE_FORMATS.items() if f <= wanted]
    return max(older) if older else min(RELEASE_FORMATS)


def uses_singular_folders(fmt: Format) -> bool:
    """True when the game reading ``fmt`` looks for ``function``/``tags/function`` (not ``functions``)."""
    return fmt >= SINGULAR_FOLDERS_FORMAT


def parse_version_set(text: str) -> list[Version]:
    """``--mc``'s forms: one release (``1.21.4``), a range (``1.16.5..1.21.11``: every known release
    between, inclusive) or a list (``1.20.4,1.21.4``); releases oldest first. Raises ValueError for
    a malformed text, an unknown listed release or a range holding no release."""
    if ".." in text:
        lo_text, hi_text = text.split("..", 1)
        lo, hi = parse_mc_version(lo_text), parse_mc_version(hi_text)
        if lo > hi:
            raise ValueError(f"'{text}': the first version comes after the second")
        found = sorted(v for v in RELEASE_FORMATS if lo <= v <= hi)
        if not found:
            raise ValueError(f"'{text}': no known release in that range")
        return found
    versions = sorted({parse_mc_version(part) for part in text.split(",") if part.strip()})
    if not versions:
        raise ValueError(f"'{text}' is not a game version (expected e.g. 1.21.4)")
    for version in versions:
        pack_format_for_version(version)
    return versions


def releases_label(versions: list[Version]) -> str:
    """Releases as runs of consecutive known releases: ``1.16.5, 1.18 – 1.19.2``."""
    ordered = sorted(RELEASE_FORMATS)
    wanted = set(versions)
    runs: list[list[Version]] = []
    for version in ordered:
        if version in wanted:
            if runs and ordered.index(version) == ordered.index(runs[-1][-1]) + 1:
                runs[-1].append(version)
            else:
                runs.append([version])
    return ", ".join(version_label(r[0]) if len(r) == 1 else f"{version_label(r[0])} – {version_label(r[-1])}"
                     for r in runs)
