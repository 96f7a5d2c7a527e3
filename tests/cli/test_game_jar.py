"""``--game-jar JAR``: one option on every subcommand that loads packs (run, profile, test, check),
the game's vanilla tags and loot tables read from its jar under the packs'; a file that is no game
jar is a usage error naming the option."""
from __future__ import annotations

import json
import zipfile

import pytest
from click.testing import CliRunner

from emulator.cli import main
from tests.backends.programs import write_pack
from tests.parser.pack.packbuild import tag

COW = {"pools": [{"rolls": 1, "entries": [{"type": "minecraft:item", "name": "minecraft:leather"}]}]}


@pytest.fixture
def jar(tmp_path):
    path = tmp_path / "client.jar"
    with zipfile.ZipFile(path, "w") as archive:
        archive.writestr("data/minecraft/tags/block/logs.json", tag("minecraft:oak_log"))
        archive.writestr("data/minecraft/loot_table/entities/cow.json", json.dumps(COW))
    return str(path)


@pytest.fixture
def pack(tmp_path):
    load = ("scoreboard objectives add o dummy\nsetblock 0 64 0 oak_log\n"
            "execute store result score #log o if block 0 64 0 #minecraft:logs\n"
            "loot spawn 0 65 0 loot minecraft:entities/cow\n"
            "execute store result score #drops o if entity @e[type=item,nbt={Item:{id:\"minecraft:leather\"}}]")
    return str(write_pack(tmp_path / "pack", {"t:load": load}, {"minecraft:load": ["t:load"]}))


def invoke(*args):
    result = CliRunner().invoke(main, list(args))
    assert result.exception is None or isinstance(result.exception, SystemExit), result.exception
    return result


def test_run_and_profile_read_the_jar(pack, jar, tmp_path):
    out = tmp_path / "r.json"
    result = invoke("run", pack, "--backend", "python", "--game-jar", jar, "--watch", "#log o", "--watch", "#drops o",
                    "--json", str(out))
    assert result.exit_code == 0, result.output
    assert json.loads(out.read_text())["scores"]["o"] == {"#log": 1, "#drops": 1}
    # without it, each vanilla read says it is not modelled and names the option
    without = invoke("run", pack, "--backend", "python", "--json", str(out))
    messages = [d["message"] for d in json.loads(out.read_text())["diagnostics"]]
    assert len(messages) == 2 and all("(pass --game-jar)" in m for m in messages), messages
    assert without.exit_code == 1
    assert invoke("profile", pack, "--game-jar", jar, "--format", "json", "-o", str(tmp_path / "p.json")).exit_code == 0


def test_check_resolves_vanilla_tags_through_the_jar(tmp_path, jar):
    root = write_pack(tmp_path / "p", {}, {})
    (root / "data/a/tags/block").mkdir(parents=True)
    (root / "data/a/tags/block/wood.json").write_text(tag("#minecraft:logs", "#minecraft:planks"))
    assert invoke("check", str(root)).exit_code == 0  # unknown without the game's data: not an error
    result = invoke("check", str(root), "--game-jar", jar)
    assert result.exit_code == 1 and "block tag #a:wood fails to load: #minecraft:planks does not exist" in result.output


@pytest.mark.parametrize("command", ["run", "profile", "check", "test"])
def test_a_file_that_is_no_game_jar_is_a_usage_error(pack, tmp_path, command):
    bad = tmp_path / "bad.jar"
    bad.write_text("no zip")
    result = invoke(command, pack, "--game-jar", str(bad))
    assert result.exit_code == 2 and "--game-jar" in result.output and "not a readable game jar" in result.output
