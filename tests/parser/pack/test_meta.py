"""pack.mcmeta: formats, description, overlays list, and the diagnostics for bad files."""
import itertools
import json

from mcfunction_parser.pack.loader import load_packs
from mcfunction_parser.pack.meta import ANY_MINOR

_names = itertools.count()


def _load_meta(make_pack, meta_text):
    root = make_pack(f"p{next(_names)}", meta_json=meta_text if isinstance(meta_text, str) else json.dumps(meta_text))
    return load_packs([root])


def test_pack_format_and_text_component_description(make_pack):
    loaded = _load_meta(make_pack, {"pack": {"pack_format": 48, "description": [
        {"text": "Pool ", "extra": [{"text": "game"}]}, "!"]}})
    info = loaded.packs[0]
    assert (info.pack_format, info.description) == (48, "Pool game!")
    assert (info.supported.min, info.supported.max) == ((48, 0), (48, ANY_MINOR))
    assert loaded.version == (1, 21, 1) and info.folder_style == "function"
    assert loaded.diagnostics == []


def test_supported_formats_forms(make_pack):
    for form in ([48, 61], {"min_inclusive": 48, "max_inclusive": 61}):
        info = _load_meta(make_pack, {"pack": {"pack_format": 48, "description": "",
                                               "supported_formats": form}}).packs[0]
        assert (info.supported.min[0], info.supported.max[0]) == (48, 61)


def test_supported_formats_must_include_pack_format(make_pack):
    loaded = _load_meta(make_pack, '{"pack": {"pack_format": 48,\n "supported_formats": [57, 61]}}')
    [error] = loaded.errors
    assert "do not include pack_format 48" in error.message
    assert (error.line, error.col) == (1, 11)


def test_min_max_format_without_pack_format(make_pack):
    # 1.21.9+: pack_format optional; an int max_format means any minor version.
    loaded = _load_meta(make_pack, {"pack": {"description": "", "min_format": [88, 0], "max_format": 94}})
    info = loaded.packs[0]
    assert info.pack_format is None
    assert (info.supported.min, info.supported.max) == ((88, 0), (94, ANY_MINOR))
    assert loaded.version == (1, 21, 11)


def test_missing_pack_mcmeta_is_an_error_but_data_still_loads(tmp_path):
    from tests.parser.pack.packbuild import tag, write_pack
    root = write_pack(tmp_path / "p", {"data/a/tags/function/t.json": tag({"id": "a:x", "required": False})})
    loaded = load_packs([root])
    [error] = loaded.errors
    assert "missing pack.mcmeta" in error.message and error.path.endswith("pack.mcmeta")
    assert "a:t" in loaded.tags


def test_bad_json_reports_line_and_column(make_pack):
    loaded = _load_meta(make_pack, '{"pack": {\n  "pack_format": 61,\n  "description": "x",,\n}}')
    [error] = loaded.errors
    assert error.message.startswith("invalid JSON")
    assert (error.line, error.col) == (3, 22)  # the second comma
    assert "^" in error.format()


def test_wrong_types_are_diagnosed(make_pack):
    loaded = _load_meta(make_pack, {"pack": {"pack_format": "61", "description": ""}})
    assert "must be an integer, not a string" in loaded.errors[0].message
    loaded = _load_meta(make_pack, {"pack": []})
    assert '"pack" object' in loaded.errors[0].message
    loaded = _load_meta(make_pack, {"pack": {"description": ""}})
    assert "pack_format\" is missing" in loaded.errors[0].message


def test_incompatible_target_version_warns(make_pack):
    root = make_pack(fmt=48)
    loaded = load_packs([root], mc_version="1.21.4")
    [warning] = loaded.warnings
    assert "not 1.21.4 (format 61)" in warning.message
    assert loaded.version == (1, 21, 4)


def test_nonexistent_pack_is_an_error(tmp_path):
    loaded = load_packs([tmp_path / "nope"])
    assert loaded.packs == [] and "does not exist" in loaded.errors[0].message


def test_description_of_any_shape(make_pack):
    shapes = {"plain": "plain", "{'extra': 5}": {"text": "a", "extra": 5},
              "ab": {"text": "a", "extra": [{"text": "b"}]}, "1true": [1, None, True]}
    for expected, description in shapes.items():
        loaded = _load_meta(make_pack, {"pack": {"pack_format": 61, "description": description}})
        assert loaded.packs[0].description == ("a" if expected.startswith("{") else expected)


def test_missing_pack_mcmeta_points_at_a_nested_pack(tmp_path):
    from tests.parser.pack.packbuild import write_pack
    write_pack(tmp_path / "outer" / "inner", {}, {"pack": {"pack_format": 61, "description": ""}})
    [error] = load_packs([tmp_path / "outer"]).errors
    assert error.message.endswith("(found one inside 'inner/': check that folder instead)")


def test_format_newer_than_every_known_release_warns_once_and_runs_as_the_newest(make_pack):
    root = make_pack(meta_json={"pack": {"description": "", "min_format": [120, 0], "max_format": 130}})
    loaded = load_packs([root])
    [warning] = loaded.warnings  # not also "the game lists it as incompatible"
    assert warning.message == ("pack format 120 is newer than every release dpemu knows: it runs as the "
                               "newest, 26.2 (format 107.1)")
    assert loaded.version == (26, 2, 0) and not loaded.errors


def test_format_newer_than_every_known_release_checked_for_an_older_mc_is_incompatible(make_pack):
    # --mc chose the release: the pack does not run as the newest one, it is one the chosen release
    # lists as incompatible (PackCompatibility.forVersion: TOO_NEW)
    root = make_pack(meta_json={"pack": {"description": "", "min_format": [120, 0], "max_format": 130}})
    loaded = load_packs([root], mc_version="1.21.4")
    [warning] = loaded.warnings
    assert warning.message == "pack supports formats 120-130, not 1.21.4 (format 61): the game lists it as incompatible"
    assert loaded.version == (1, 21, 4)


def test_26_1_pack_runs_as_26_1_2(make_pack):
    loaded = load_packs([make_pack(meta_json={"pack": {"description": "", "min_format": [101, 1], "max_format": [101, 1]}})])
    assert loaded.version == (26, 1, 2) and not loaded.warnings


def test_decimal_format_numbers_are_read_whole_with_a_warning(make_pack):
    # DataFixerUpper JsonOps.getNumberValue accepts any JSON number and Codec.INT keeps
    # Number.intValue() of it: Gson's LazilyParsedNumber("101.1").intValue() is 101 (BigDecimal
    # truncation), so the game loads "min_format": 101.1 as [101, 0] where [101, 1] was meant.
    loaded = _load_meta(make_pack, '{"pack": {"description": "",\n "min_format": 101.1, "max_format": 101.1}}')
    info = loaded.packs[0]
    assert (info.supported.min, info.supported.max) == ((101, 0), (101, ANY_MINOR))
    assert not loaded.errors and loaded.version == (26, 1, 2)
    first, second = [w for w in loaded.warnings if "pack.mcmeta" in w.message]
    assert first.message == ('pack.mcmeta: "min_format" 101.1 is read as 101 (the game keeps the whole int part '
                             'of a number; a minor version is written [major, minor])')
    assert (first.line, first.col) == (2, 2) and '"max_format" 101.1' in second.message


def test_decimal_numbers_in_lists_and_ranges_are_truncated_too(make_pack):
    info = _load_meta(make_pack, {"pack": {"pack_format": 48.0, "description": "",
                                           "supported_formats": {"min_inclusive": 48, "max_inclusive": 61.9}}}).packs[0]
    assert info.pack_format == 48 and (info.supported.min[0], info.supported.max[0]) == (48, 61)
    info = _load_meta(make_pack, {"pack": {"description": "", "min_format": [94, 1.5], "max_format": 94}}).packs[0]
    assert info.supported.min == (94, 1)


def test_a_boolean_or_string_format_stays_an_error(make_pack):
    # JsonOps.getNumberValue refuses a string ("Not a number"); a boolean reads as 1 or 0, a format
    # no release has, and before 1.20.2 GsonHelper.convertToInt refused it outright.
    for bad in (True, "48", None):
        loaded = _load_meta(make_pack, {"pack": {"pack_format": bad, "description": ""}})
        assert len(loaded.errors) == 1, bad


def test_a_pack_format_outside_the_declared_range_does_not_choose_the_release(make_pack):
    # pack_format 107 (107.0) beside min_format [107, 1]: the pack runs as the release its range
    # names (26.2), not as 26.1.2 only to be told that release lists it as incompatible
    meta = {"pack": {"description": "", "pack_format": 107, "min_format": [107, 1], "max_format": [107, 1]}}
    loaded = load_packs([make_pack(meta_json=meta)])
    assert loaded.version == (26, 2, 0) and not loaded.warnings
    # a pack_format inside the range still chooses (supported_formats [15, 48] written for 15: 1.20.1)
    meta = {"pack": {"description": "", "pack_format": 15, "supported_formats": [15, 48]}}
    assert load_packs([make_pack(meta_json=meta)]).version == (1, 20, 1)
