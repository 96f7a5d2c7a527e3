"""The pack_format <-> release table (minecraft.wiki "Pack format", data pack formats)."""
import pytest

from mcfunction_parser.pack.versions import (
    LATEST_RELEASE, RELEASE_FORMATS, format_label, pack_format_for_version, parse_mc_version,
    newer_than_known, uses_singular_folders, version_for_pack_format, version_label,
)


@pytest.mark.parametrize("text, version", [("1.21.4", (1, 21, 4)), ("1.21", (1, 21, 0)),
                                           (" 1.16.5 ", (1, 16, 5)), ("1.21.11", (1, 21, 11)),
                                           ("26.1", (26, 1, 0)), ("26.1.2", (26, 1, 2))])
def test_parse_mc_version(text, version):
    assert parse_mc_version(text) == version


@pytest.mark.parametrize("text", ["", "1", "1.21.x", "v1.21", "1.21.4.1", "latest"])
def test_parse_mc_version_rejects_malformed(text):
    with pytest.raises(ValueError, match="not a game version"):
        parse_mc_version(text)


# One release per format from the wiki's data pack table, including both ends of each range.
@pytest.mark.parametrize("version, fmt", [
    ("1.16.1", (5, 0)), ("1.16.2", (6, 0)), ("1.16.5", (6, 0)), ("1.17.1", (7, 0)),
    ("1.18.1", (8, 0)), ("1.18.2", (9, 0)), ("1.19.3", (10, 0)), ("1.19.4", (12, 0)),
    ("1.20.1", (15, 0)), ("1.20.2", (18, 0)), ("1.20.4", (26, 0)), ("1.20.6", (41, 0)),
    ("1.21", (48, 0)), ("1.21.1", (48, 0)), ("1.21.3", (57, 0)), ("1.21.4", (61, 0)),
    ("1.21.5", (71, 0)), ("1.21.6", (80, 0)), ("1.21.8", (81, 0)), ("1.21.10", (88, 0)),
    ("1.21.11", (94, 1)), ("26.1", (101, 1)), ("26.1.1", (101, 1)), ("26.1.2", (101, 1)), ("26.2", (107, 1)),
])
def test_release_formats(version, fmt):
    assert pack_format_for_version(parse_mc_version(version)) == fmt


def test_unknown_release_is_an_error():
    with pytest.raises(ValueError, match="unknown release 1.21.99"):
        pack_format_for_version((1, 21, 99))


@pytest.mark.parametrize("fmt, version", [
    (48, "1.21.1"), (61, "1.21.4"), (6, "1.16.5"), ((94, 1), "1.21.11"),
    (50, "1.21.1"),  # a snapshot-only format: the newest release before it
    ((101, 0), "1.21.11"),  # 26.1's pre-release format: the newest release before it
    ((101, 1), "26.1.2"), ((107, 1), "26.2"),
    (200, "26.2"),  # newer than every release: the latest
    (1, "1.13"),
])
def test_version_for_pack_format(fmt, version):
    assert version_label(version_for_pack_format(fmt)) == version


def test_formats_never_decrease_with_releases():
    ordered = [RELEASE_FORMATS[v] for v in sorted(RELEASE_FORMATS)]
    assert ordered == sorted(ordered)
    assert LATEST_RELEASE == (26, 2, 0)


def test_year_numbered_releases_sort_after_1_x():
    assert sorted(RELEASE_FORMATS)[-5:] == [(1, 21, 11), (26, 1, 0), (26, 1, 1), (26, 1, 2), (26, 2, 0)]
    assert version_label((26, 1, 0)) == "26.1" and version_label((26, 1, 2)) == "26.1.2"


@pytest.mark.parametrize("fmt, newer", [((107, 1), False), ((107, 2), True), (108, True), (94, False)])
def test_newer_than_known(fmt, newer):
    assert newer_than_known(fmt) is newer


def test_folder_rename_at_1_21():
    assert not uses_singular_folders(pack_format_for_version((1, 20, 6)))
    assert uses_singular_folders(pack_format_for_version((1, 21, 0)))


def test_labels():
    assert format_label((94, 1)) == "94.1" and format_label((61, 0)) == "61"
    assert version_label((1, 21, 0)) == "1.21"


def test_newest_formats_checked_against_independent_sources():
    # 1.21.9 -> 88.0: minecraft.wiki "Pack format" (2026-02 copy: the 1.21.9 pack.mcmeta example has
    # "min_format": 88, "max_format": 88). 1.21.10 -> 88 and 1.21.11 -> 94: version tables of two
    # public projects ({"1.21.9": 88, "1.21.10": 88, "1.21.11": 94}) and a pack migrator's 1.21.11
    # step "Update pack format to 94". The minor .1: the pack.mcmeta a 1.21.11 Paper server writes
    # for its own data pack reads "min_format": [94, 1]. (The wiki table row itself could not be
    # read here; re-check it when the table is reachable.)
    assert pack_format_for_version((1, 21, 9)) == (88, 0)
    assert pack_format_for_version((1, 21, 10)) == (88, 0)
    assert pack_format_for_version((1, 21, 11)) == (94, 1)
