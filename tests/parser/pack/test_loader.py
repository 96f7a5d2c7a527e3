"""Loading functions: folder names by game version, overlays, several packs, file decoding."""
import time
import zipfile

from mcfunction_parser.pack.loader import load_packs
from tests.parser.pack.packbuild import meta, write_pack


def test_new_format_reads_function_and_ignores_functions(make_pack):
    root = make_pack(fmt=61, files={"data/a/function/x.mcfunction": "say x\n",
                                    "data/a/function/sub/dir/y.mcfunction": "say y\n",
                                    "data/a/functions/old.mcfunction": "say old\n",
                                    "data/a/functions/old2.mcfunction": "say old\n"})
    loaded = load_packs([root])
    assert sorted(loaded.functions) == ["a:sub/dir/y", "a:x"]
    assert loaded.packs[0].folder_style == "function"
    [warning] = loaded.warnings
    assert warning.message == ("2 file(s) in 'data/a/functions/' ignored: 1.21.4 (format 61) "
                               "reads 'data/a/function/' instead")
    assert warning.path == f"{root}/data/a/functions"


def test_old_format_reads_functions(make_pack):
    root = make_pack(fmt=26, files={"data/a/functions/x.mcfunction": "say x\n",
                                    "data/a/function/new.mcfunction": "say new\n"})
    loaded = load_packs([root])
    assert list(loaded.functions) == ["a:x"] and loaded.version == (1, 20, 4)
    assert "reads 'data/a/functions/'" in loaded.warnings[0].message


def test_mc_version_overrides_the_pack(make_pack):
    root = make_pack(fmt=26, files={"data/a/functions/x.mcfunction": "say x\n"})
    loaded = load_packs([root], mc_version="1.21.4")
    assert loaded.version == (1, 21, 4) and loaded.functions == {}
    assert loaded.packs[0].folder_style == "function"


def test_function_fields_and_sources(make_pack):
    root = make_pack(files={"data/a/function/x.mcfunction": "say one\r\nsay two\rsay three\n"})
    loaded = load_packs([root])
    function = loaded.functions["a:x"]
    shown = f"{root}/data/a/function/x.mcfunction"
    assert (function.id, function.path, function.pack) == ("a:x", shown, str(root))
    assert loaded.sources[shown] == ["say one", "say two", "say three"]


def test_non_files_and_other_suffixes_are_not_functions(make_pack):
    root = make_pack(files={"data/a/function/notes.txt": "hello", "data/a/function/x.mcfunction": "",
                            "data/a/function/Bad Name.mcfunction": "say x\n"})
    loaded = load_packs([root])
    assert list(loaded.functions) == ["a:x"]
    [warning] = loaded.warnings
    assert "invalid resource location 'a:Bad Name'" in warning.message


def test_overlays_replace_files_of_the_matching_format(tmp_path):
    overlays = {"entries": [{"directory": "ov_old", "formats": [10, 47]},
                            {"directory": "ov_a", "formats": {"min_inclusive": 48, "max_inclusive": 61}},
                            {"directory": "ov_b", "formats": 61}]}
    root = write_pack(tmp_path / "p", {
        "data/a/function/x.mcfunction": "say base\n",
        "data/a/function/keep.mcfunction": "say keep\n",
        "ov_old/data/a/function/x.mcfunction": "say old\n",
        "ov_a/data/a/function/x.mcfunction": "say a\n",
        "ov_a/data/a/function/added.mcfunction": "say added\n",
        "ov_b/data/a/function/x.mcfunction": "say b\n",
    }, {**meta(61), "overlays": overlays})
    loaded = load_packs([root])
    assert loaded.packs[0].overlays == ["ov_a", "ov_b"]
    assert sorted(loaded.functions) == ["a:added", "a:keep", "a:x"]
    assert loaded.functions["a:x"].path == f"{root}/ov_b/data/a/function/x.mcfunction"  # later wins
    older = load_packs([root], mc_version="1.20.4")
    assert older.packs[0].overlays == ["ov_old"]
    # overlays arrived in 1.20.2 (minecraft.wiki "Pack.mcmeta" history): older games ignore them
    assert load_packs([root], mc_version="1.20.1").packs[0].overlays == []


def test_overlay_min_max_format_and_bad_directory(tmp_path):
    good = {"entries": [{"directory": "new", "min_format": [94, 1], "max_format": 94}]}
    root = write_pack(tmp_path / "p", {"new/data/a/function/x.mcfunction": "say x\n"},
                      {"pack": {"description": "", "min_format": 88, "max_format": 94}, "overlays": good})
    assert load_packs([root]).packs[0].overlays == ["new"]
    assert load_packs([root], mc_version="1.21.10").packs[0].overlays == []
    bad = write_pack(tmp_path / "q", {}, {**meta(61), "overlays": {"entries": [{"directory": "Up", "formats": 61}]}})
    assert "overlay needs a \"directory\"" in load_packs([bad]).errors[0].message


def test_later_pack_overrides_functions(make_pack):
    lib = make_pack("lib", files={"data/lib/function/f.mcfunction": "say lib\n",
                                  "data/lib/function/g.mcfunction": "say g\n"})
    game = make_pack("game", files={"data/lib/function/f.mcfunction": "say game\n"})
    loaded = load_packs([lib, game])
    assert loaded.functions["lib:f"].path.startswith(str(game))
    assert loaded.functions["lib:g"].path.startswith(str(lib))
    [info] = loaded.infos
    assert "function lib:f overrides" in info.message and info.path.startswith(str(game))
    assert [p.root for p in loaded.packs] == [lib, game]


def test_version_is_the_newest_any_pack_targets(make_pack):
    assert load_packs([make_pack("a", fmt=48), make_pack("b", fmt=61)]).version == (1, 21, 4)


def test_invalid_utf8_is_a_diagnostic_with_position_and_the_rest_loads(make_pack):
    root = make_pack(files={"data/a/function/bad.mcfunction": b"say ok\nsay caf\xe9 au lait\n",
                            "data/a/function/good.mcfunction": "say fine\n"})
    loaded = load_packs([root])
    [warning] = loaded.warnings
    assert "invalid UTF-8 byte 0xe9 at byte offset 14" in warning.message
    assert (warning.line, warning.col) == (2, 8)
    assert sorted(loaded.functions) == ["a:bad", "a:good"]
    assert loaded.sources[warning.path][1] == "say caf\ufffd au lait"  # the game's replacement


def test_bom_in_function_is_an_error_but_json_tolerates_it(make_pack):
    # Gson's JsonReader.fillBuffer consumes a leading U+FEFF; Java's UTF-8 InputStreamReader (used
    # for function lines) keeps it, so it lands in the first command.
    root = make_pack(files={"data/a/function/x.mcfunction": b"\xef\xbb\xbfsay x\n",
                            "data/a/tags/function/t.json": b'\xef\xbb\xbf{"values": ["a:x"]}'})
    loaded = load_packs([root])
    [error] = loaded.errors
    assert "byte order mark" in error.message and error.path.endswith("x.mcfunction")
    assert loaded.resolve_tag("a:t") == ["a:x"]


def test_one_megabyte_line(make_pack):
    line = "say " + "x" * 1_000_000
    root = make_pack(files={"data/a/function/big.mcfunction": line + "\n"})
    start = time.perf_counter()
    loaded = load_packs([root])
    assert time.perf_counter() - start < 5
    assert loaded.sources[loaded.functions["a:big"].path] == [line]


def test_advancement_rewards_are_recorded(make_pack):
    # Advancement.CODEC: "Advancement criteria cannot be empty"
    root = make_pack(files={"data/a/advancement/got.json": '{"criteria": {"t": {"trigger": "minecraft:tick"}},\n'
                                                            ' "rewards": {"function": "a:reward"}}',
                            "data/a/advancements/old.json": '{"rewards": {"function": "a:old"}}'})
    loaded = load_packs([root])
    [loc] = loaded.advancement_rewards["a:reward"]
    assert (loc.line, loc.col) == (2, 26)
    assert "a:old" not in loaded.advancement_rewards


def test_empty_and_partial_packs(tmp_path, make_pack):
    empty = tmp_path / "empty"
    empty.mkdir()
    loaded = load_packs([empty])
    assert [d.message for d in loaded.errors] == [
        "missing pack.mcmeta: the game does not recognise this as a data pack"]
    assert load_packs([make_pack()]).diagnostics == []


def test_line_breaks_match_the_game(make_pack):
    # BufferedReader.lines() ends a line at \n, \r\n or a lone \r: the parser sees those lines.
    root = make_pack(files={"data/a/function/x.mcfunction": "say a\rsay b\r\nexecute as @e[tag=x run say\r\n"})
    loaded = load_packs([root])
    [error] = loaded.errors
    assert (error.line, error.col) == (3, 21) and error.source_line == "execute as @e[tag=x run say"
    assert len(loaded.refused["a:x"].commands) == 2  # parsed for check, refused by the game


def test_trailing_blank_lines_count(make_pack):
    root = make_pack(files={"data/a/function/x.mcfunction": "say a\n\n\n", "data/a/function/y.mcfunction": "say a"})
    loaded = load_packs([root])
    assert loaded.functions["a:x"].lines == 3 and loaded.functions["a:y"].lines == 1


def test_filter_block_hides_files_of_earlier_packs_only(tmp_path):
    # minecraft.wiki "Pack.mcmeta" filter; matching follows the game's ResourceFilterSection.
    lib = write_pack(tmp_path / "lib", {"data/lib/function/old/a.mcfunction": "say a\n",
                                        "data/lib/function/keep.mcfunction": "say k\n",
                                        "data/other/function/old/b.mcfunction": "say b\n"}, meta(61))
    game = write_pack(tmp_path / "game", {"data/lib/function/old/own.mcfunction": "say own\n"},
                      {**meta(61), "filter": {"block": [{"namespace": "lib", "path": "function/old/.*"}]}})
    loaded = load_packs([lib, game])
    assert sorted(loaded.functions) == ["lib:keep", "lib:old/own", "other:old/b"]
    old_lib = write_pack(tmp_path / "old_lib", {"data/lib/functions/old/a.mcfunction": "say a\n"}, meta(9))
    old_game = write_pack(tmp_path / "old_game", {}, {**meta(9), "filter": {"block": [{"path": ".*"}]}})
    assert "lib:old/a" in load_packs([old_lib, old_game]).functions  # 1.18.2: no filter yet (1.19)
    assert load_packs([old_lib, old_game], mc_version="1.19").functions == {}
    assert sorted(load_packs([game, lib]).functions) == [
        "lib:keep", "lib:old/a", "lib:old/own", "other:old/b"]


def test_filter_with_bad_regex_is_diagnosed(tmp_path):
    root = write_pack(tmp_path / "p", {}, {**meta(61), "filter": {"block": [{"path": "function/("}]}})
    [error] = load_packs([root]).errors
    assert "not a valid regular expression" in error.message


def test_zip_pack_loads_like_a_folder(tmp_path):
    import zipfile
    overlays = {"entries": [{"directory": "ov", "formats": 61}]}
    folder = write_pack(tmp_path / "folder", {
        "data/a/function/x.mcfunction": "say x\nexecute as @e[tag=a run say\n",
        "ov/data/a/function/y.mcfunction": "say y\n",
        "data/a/tags/function/t.json": '{"values": ["a:y"]}'}, {**meta(61), "overlays": overlays})
    archive = tmp_path / "pack.zip"
    with zipfile.ZipFile(archive, "w") as zf:  # no explicit folder entries, as many zip tools write
        for path in sorted(folder.rglob("*")):
            if path.is_file():
                zf.write(path, path.relative_to(folder).as_posix())
    loaded = load_packs([archive])
    assert sorted(loaded.functions) == ["a:y"] and loaded.packs[0].overlays == ["ov"]
    assert sorted(loaded.refused) == ["a:x"]  # its second line does not parse
    assert loaded.resolve_tag("a:t") == ["a:y"]
    [error] = loaded.errors
    assert (error.path, error.line, error.col) == (f"{archive}/data/a/function/x.mcfunction", 2, 21)
    assert loaded.functions["a:y"].path == f"{archive}/ov/data/a/function/y.mcfunction"
    assert loaded.packs[0].root == archive


def test_a_plain_file_is_not_a_pack(tmp_path):
    path = tmp_path / "notes.txt"
    path.write_text("hello")
    loaded = load_packs([path])
    assert loaded.packs == [] and loaded.errors[0].message == "pack is not a folder or a .zip file"


def test_both_folders_in_a_pack_for_both_sides_of_the_rename_is_only_info(tmp_path):
    files = {"data/a/functions/x.mcfunction": "say old\n", "data/a/function/x.mcfunction": "say new\n"}
    dual = write_pack(tmp_path / "dual", files, meta(48, supported_formats=[26, 61]))
    loaded = load_packs([dual])
    assert loaded.warnings == [] and "'data/a/functions/' ignored" in loaded.infos[0].message
    assert load_packs([dual], mc_version="1.20.4").functions["a:x"].path.endswith("functions/x.mcfunction")


def test_symbolic_link_loop_is_walked_once(make_pack):
    root = make_pack(files={"data/a/function/x.mcfunction": "say x\n"})
    (root / "data/a/function/loop").symlink_to(root / "data/a/function", target_is_directory=True)
    assert list(load_packs([root]).functions) == ["a:x"]


def test_a_truncated_zip_is_named_a_corrupt_archive(tmp_path):
    good = tmp_path / "good.zip"
    with zipfile.ZipFile(good, "w") as z:
        z.writestr("pack.mcmeta", '{"pack": {"pack_format": 48, "description": ""}}')
        z.writestr("data/a/function/x.mcfunction", "say hi\n" * 50)
    broken = tmp_path / "broken.zip"
    broken.write_bytes(good.read_bytes()[:120])
    loaded = load_packs([broken])
    assert loaded.packs == [] and loaded.errors[0].message == "pack is a corrupt .zip archive"
