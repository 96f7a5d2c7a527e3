"""``dpemu check``: exit codes, human output, JSON output."""
import json
from pathlib import Path

from click.testing import CliRunner

from emulator.cli import main


def pack(root: Path, files: dict[str, str], pack_format: int = 61) -> Path:
    root.mkdir(parents=True)
    (root / "pack.mcmeta").write_text(json.dumps({"pack": {"pack_format": pack_format, "description": ""}}))
    for rel, text in files.items():
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        (root / rel).write_text(text)
    return root


CLEAN = {"data/a/function/load.mcfunction": "scoreboard objectives add o dummy\nscoreboard players set x o 1\n",
         "data/minecraft/tags/function/load.json": '{"values": ["a:load"]}'}


def run(*args):
    return CliRunner().invoke(main, ["check", *map(str, args)])


def test_clean_pack_exits_0_with_summary(tmp_path):
    result = run(pack(tmp_path / "p", CLEAN))
    assert result.exit_code == 0
    assert result.output == "3 files, 1 function, 2 commands: 0 errors, 0 warnings\n"


def test_warnings_and_infos_still_exit_0(tmp_path):
    files = {**CLEAN, "data/a/function/spare.mcfunction": "scoreboard players set x undefined 1\n"}
    result = run(pack(tmp_path / "p", files))
    assert result.exit_code == 0
    assert "warning: objective 'undefined' is used but never created" in result.output
    assert "info: function a:spare is never referenced" in result.output
    assert result.output.splitlines()[-1].endswith("0 errors, 1 warning")


def test_errors_exit_1_with_location_and_caret(tmp_path):
    root = pack(tmp_path / "p", {**CLEAN, "data/a/function/load.mcfunction": "say ok\nexecute as @e[tag=x run say\n"})
    result = run(root)
    assert result.exit_code == 1
    lines = result.output.splitlines()
    assert lines[0].startswith(f"{root}/data/a/function/load.mcfunction:2:21: error: ")
    assert lines[1] == "    execute as @e[tag=x run say"
    assert lines[2] == "    " + " " * 20 + "^"
    # the second error: the tag naming the function fails, as the function fails to load
    assert lines[-1] == "3 files, 1 function, 1 command: 2 errors, 0 warnings"


def test_json_output_is_one_object(tmp_path):
    root = pack(tmp_path / "p", {**CLEAN, "data/a/function/extra.mcfunction": "function a:nope\n"})
    result = run(root, "--json")
    assert result.exit_code == 1
    data = json.loads(result.output)
    assert list(data) == ["files", "functions", "commands", "lines", "errors", "warnings", "infos", "versions", "seconds"]
    assert (data["files"], data["functions"], data["commands"], data["lines"]) == (4, 2, 3, 3)
    assert data["errors"] == [{"path": f"{root}/data/a/function/extra.mcfunction", "line": 1, "col": 1,
                               "message": "unknown function a:nope"}]
    assert data["infos"][0]["message"].startswith("function a:extra is never referenced")
    assert isinstance(data["seconds"], float)
    assert data["versions"] == ["1.21.4"]  # pack_format 61


def test_usage_errors_exit_2(tmp_path):
    assert run(tmp_path / "missing").exit_code == 2
    a_file = tmp_path / "file.txt"
    a_file.write_text("x")
    not_a_pack = run(a_file)
    assert not_a_pack.exit_code == 2 and "is not a folder or a .zip file" in not_a_pack.output
    root = pack(tmp_path / "p", CLEAN)
    bad_version = run(root, "--mc", "1.99")
    assert bad_version.exit_code == 2 and "unknown release 1.99" in bad_version.output
    assert run(root, "--mc", "latest").exit_code == 2
    assert CliRunner().invoke(main, ["check"]).exit_code == 2


def test_mc_option_changes_the_folders_read(tmp_path):
    root = pack(tmp_path / "p", {"data/a/functions/old.mcfunction": "say hi\n"}, pack_format=26)
    assert "1 function," in run(root).output
    newer = run(root, "--mc", "1.21.4")
    assert "0 functions" in newer.output and "ignored: 1.21.4 (format 61)" in newer.output


def test_several_packs_in_order(tmp_path):
    lib = pack(tmp_path / "lib", {"data/lib/function/api.mcfunction": "say lib\n"})
    game = pack(tmp_path / "game", {**CLEAN, "data/a/function/load.mcfunction": "function lib:api\nfunction a:typo\n"})
    assert run(game).exit_code == 1
    assert "unknown function lib:api" not in run(lib, game).output


def test_a_call_into_a_namespace_no_loaded_pack_defines_is_a_warning_naming_it(tmp_path):
    # FunctionArgument.parse only reads the id: the game loads the calling function and fails the
    # call when it runs, so a library expected beside the pack is not a load error
    lib = pack(tmp_path / "lib", {"data/lib/function/api.mcfunction": "say lib\n",
                                  "data/lib/function/broken.mcfunction": "sayy\n"})
    game = pack(tmp_path / "game", {**CLEAN, "data/a/function/load.mcfunction": "function lib:api\nfunction #lib:hooks\n"})
    alone = run(game)
    assert alone.exit_code == 0
    assert "warning: unknown function lib:api: no loaded pack defines the namespace 'lib'" in alone.output
    assert "unknown function tag #lib:hooks: no loaded pack defines the namespace 'lib'" in alone.output
    beside = run(game, "--with", lib)
    assert "lib:api" not in beside.output and "sayy" not in beside.output  # the library's own findings too
    assert "unknown function tag #lib:hooks" in beside.output and beside.exit_code == 1  # lib is there now


def test_a_typo_in_the_packs_own_namespace_stays_an_error(tmp_path):
    game = pack(tmp_path / "game", {**CLEAN, "data/a/function/extra.mcfunction": "function a:nope\n"})
    result = run(game)
    assert result.exit_code == 1 and "error: unknown function a:nope" in result.output


def test_empty_and_partial_packs_do_not_crash(tmp_path):
    empty = tmp_path / "empty"
    empty.mkdir()
    result = run(empty)
    assert result.exit_code == 1 and "missing pack.mcmeta" in result.output
    assert "Traceback" not in result.output
    partial = pack(tmp_path / "partial", {})
    result = run(partial)
    assert result.exit_code == 0 and result.output == "1 file, 0 functions, 0 commands: 0 errors, 0 warnings\n"


def test_binary_garbage_gives_diagnostics_not_a_traceback(tmp_path):
    root = pack(tmp_path / "p", {})
    (root / "data/a/function").mkdir(parents=True)
    (root / "data/a/function/bin.mcfunction").write_bytes(bytes(range(256)) * 4)
    (root / "data/a/tags/function").mkdir(parents=True)
    (root / "data/a/tags/function/t.json").write_bytes(b"\x00\xff{")
    result = run(root, "--json")
    assert result.exception is None or isinstance(result.exception, SystemExit)
    data = json.loads(result.output)
    assert data["errors"] and result.exit_code == 1


def test_zip_pack(tmp_path):
    import zipfile
    archive = tmp_path / "pack.zip"
    with zipfile.ZipFile(archive, "w") as zf:
        zf.writestr("pack.mcmeta", json.dumps({"pack": {"pack_format": 61, "description": ""}}))
        for rel, text in CLEAN.items():
            zf.writestr(rel, text)
    result = run(archive)
    assert result.exit_code == 0 and result.output.endswith("1 function, 2 commands: 0 errors, 0 warnings\n")


# ---------------------------------------------------------------------- several releases
GATED = {  # supports 1.17 - 1.20.1; `ride` exists from 1.19.4 (23w03a), the version-gated variant
    "data/a/functions/load.mcfunction": "scoreboard objectives add o dummy\n",
    "data/a/functions/v19/mount.mcfunction": "ride @s mount @e[type=minecraft:pig,limit=1]\n",
    "data/minecraft/tags/functions/load.json": '{"values": ["a:load"]}',
    "data/minecraft/tags/functions/tick.json": '{"values": ["a:v19/mount"]}',
}


def gated_pack(root: Path) -> Path:
    root = pack(root, GATED)
    (root / "pack.mcmeta").write_text(json.dumps({"pack": {
        "pack_format": 7, "description": "", "supported_formats": {"min_inclusive": 7, "max_inclusive": 15}}}))
    return root


def test_a_pack_declaring_a_range_is_checked_over_it_with_findings_tagged_by_release(tmp_path):
    result = run(gated_pack(tmp_path / "p"))
    assert result.exit_code == 1
    errors = [line for line in result.output.splitlines() if ": error: " in line]
    assert errors and all(line.endswith("(only in 1.17 – 1.19.3)") for line in errors), errors
    assert "unknown command 'ride'" in errors[0] or "ride" in errors[0]
    assert result.output.splitlines()[-1].endswith("(checked for 1.17 – 1.20.1)")


def test_mc_takes_a_range_and_a_list_and_json_carries_the_releases(tmp_path):
    root = gated_pack(tmp_path / "p")
    report = json.loads(run(root, "--mc", "1.19.4,1.20.1", "--json").output)
    assert report["errors"] == [] and report["versions"] == ["1.19.4", "1.20.1"]
    report = json.loads(run(root, "--mc", "1.18..1.19.4", "--json").output)
    assert report["errors"] and all(e["versions"] == ["1.18", "1.18.1", "1.18.2", "1.19", "1.19.1", "1.19.2", "1.19.3"]
                                    for e in report["errors"])
    assert report["versions"][0] == "1.18" and report["versions"][-1] == "1.19.4"


def test_a_finding_true_in_every_release_is_not_tagged(tmp_path):
    files = {**GATED, "data/a/functions/v19/mount.mcfunction": "scoreboard players sett x o 1\n"}
    root = pack(tmp_path / "p", files)
    result = run(root, "--mc", "1.17..1.20.1")
    errors = [line for line in result.output.splitlines() if ": error: " in line]
    assert errors and not any("only in" in line for line in errors)


def test_bad_version_sets_are_usage_errors(tmp_path):
    root = pack(tmp_path / "p", CLEAN)
    for bad in ("1.21.4..1.20", "1.99", "1.20.1,x", "0.1..0.2"):
        result = run(root, "--mc", bad)
        assert result.exit_code == 2, (bad, result.output)
