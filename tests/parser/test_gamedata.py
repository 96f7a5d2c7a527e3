"""The game data module: which release's data answers for a release, and the missing-data error."""
from __future__ import annotations

import json

import pytest

from mcfunction_parser import gamedata
from mcfunction_parser.pack.versions import RELEASE_FORMATS
from mcfunction_parser.parse import parse_function


def test_every_known_release_has_a_command_tree_or_a_stand_in(tmp_path, monkeypatch):
    """dpemu ships trees up to 26.1; a later release (26.2) is checked against the newest one, and
    stand_in says how to get its own."""
    monkeypatch.setenv("DPEMU_GAMEDATA", str(tmp_path))
    newest = max(gamedata._index()["commands"])
    for version in RELEASE_FORMATS:
        release = gamedata.tree_release(version)
        if version[:2] > newest[:2]:
            assert release == newest and "--reports" in gamedata.stand_in(version)
        else:
            assert release[:2] >= version[:2]
            assert (gamedata.stand_in(version) is None) is (release[:2] == version[:2])
        assert "execute" in gamedata.command_tree(version)["children"]


def test_a_release_uses_its_own_tree_or_the_oldest_after_it():
    assert gamedata.tree_release((1, 20, 3)) == (1, 20, 3)
    # 1.20.4 is 1.20.3's hotfix (both data pack format 26): its tree, not 1.20.6's, where 1.20.5's
    # new syntax is (attribute modifiers by id and add_value, item components)
    assert gamedata.tree_release((1, 20, 4)) == (1, 20, 3)
    assert gamedata.tree_release((1, 20, 5)) == (1, 20, 6)
    assert gamedata.tree_release((1, 21, 0)) == (1, 21, 1)
    assert [gamedata.tree_release((1, 21, patch)) for patch in range(1, 12)] == [
        (1, 21, 1), (1, 21, 4), (1, 21, 4), (1, 21, 4), (1, 21, 5), (1, 21, 8), (1, 21, 8), (1, 21, 8),
        (1, 21, 10), (1, 21, 10), (1, 21, 11)]
    assert gamedata.tree_release((1, 13, 0)) == (1, 16, 5)


def test_trees_follow_the_releases():
    # `return run` came back in 23w41a (1.20.3); 1.20.2 has only `return <value>`
    assert set(gamedata.command_tree((1, 20, 2))["children"]["return"]["children"]) == {"value"}
    assert "run" in gamedata.command_tree((1, 20, 3))["children"]["return"]["children"]
    assert "transfer" in gamedata.command_tree((1, 20, 5))["children"]
    # each 1.21 patch's own commands: rotate (1.21.2), test (1.21.5), waypoint and dialog (1.21.6),
    # fetchprofile (1.21.9), stopwatch (1.21.11)
    added = {(1, 21, 2): "rotate", (1, 21, 5): "test", (1, 21, 6): "dialog", (1, 21, 9): "fetchprofile",
             (1, 21, 11): "stopwatch"}
    for version, command in added.items():
        before = (version[0], version[1], version[2] - 1)
        assert command in gamedata.command_tree(version)["children"]
        assert command not in gamedata.command_tree(before)["children"], (before, command)
    # setworldspawn's angle became a rotation in 1.21.9
    spawn = lambda v: set(gamedata.command_tree(v)["children"]["setworldspawn"]["children"]["pos"]["children"])  # noqa: E731
    assert spawn((1, 21, 1)) == {"angle"} and spawn((1, 21, 9)) == {"rotation"}


def test_a_release_after_every_tree_says_how_to_get_its_own(tmp_path, monkeypatch):
    monkeypatch.setenv("DPEMU_GAMEDATA", str(tmp_path))
    message = gamedata.stand_in((26, 2, 0))
    assert "Minecraft 26.2" in message and "--reports" in message and str(tmp_path / "26.2") in message
    assert "against the 26.1 command tree" in message and "-DbundlerMainClass" in message
    assert gamedata.stand_in((26, 1, 2)) is None


def test_releases_before_every_tree_name_the_tree_they_are_checked_with(tmp_path, monkeypatch):
    """1.13 – 1.15 have no tree in any maintained package: checked with 1.16.5's, said once, with
    the pre-1.18 way to run the data generator (the server jar is not a bundler yet)."""
    monkeypatch.setenv("DPEMU_GAMEDATA", str(tmp_path))
    message = gamedata.stand_in((1, 14, 4))
    assert "against the 1.16.5 command tree" in message and "Minecraft 1.14.4" in message
    assert "java -cp server.jar net.minecraft.data.Main --reports" in message
    assert gamedata.stand_in((1, 16, 0)) is None and gamedata.stand_in((1, 21, 4)) is None


def test_the_games_own_reports_are_read_for_any_release(tmp_path, monkeypatch):
    monkeypatch.setenv("DPEMU_GAMEDATA", str(tmp_path))
    folder = tmp_path / "26.9"
    folder.mkdir()
    tree = {"type": "root", "children": {"say": {"type": "literal"}}}
    (folder / "commands.json").write_text(json.dumps(tree))
    (folder / "registries.json").write_text(json.dumps(
        {"minecraft:item": {"entries": {"minecraft:stone": {"protocol_id": 1}}}}))
    (folder / "blocks.json").write_text(json.dumps(
        {"minecraft:lever": {"properties": {"powered": ["true", "false"]}, "states": [
            {"id": 1, "properties": {"powered": "true"}}, {"id": 2, "default": True, "properties": {"powered": "false"}}]},
         "minecraft:stone": {"states": [{"id": 3, "default": True}]}}))
    assert gamedata.tree_release((26, 9, 0)) == (26, 9, 0)
    assert gamedata.command_tree((26, 9, 0)) == tree
    assert gamedata.registry("item", (26, 9, 0)) == {"stone"}
    assert gamedata.registry_release((26, 9, 0)) == ((26, 9, 0), True)
    assert gamedata.block_states("minecraft:lever", (26, 9, 0)) == {"powered": ("true", "false")}
    # the blocks report marks each block's default state
    assert gamedata.default_state("lever", (26, 9, 0)) == {"powered": "false"}
    assert gamedata.default_state("stone", (26, 9, 0)) == {}
    assert gamedata.default_state("no_such_block", (26, 9, 0)) is None


def test_registries_and_block_states():
    assert "diamond" in gamedata.registry("item", (1, 21, 4))
    assert "zombie" in gamedata.registry("entity_type", (1, 13, 0))
    assert "warden" not in gamedata.registry("entity_type", (1, 18, 2))  # 1.19
    assert "warden" in gamedata.registry("entity_type", (1, 19, 0))
    assert "unluck" in gamedata.registry("mob_effect", (1, 16, 5))
    assert "max_health" in gamedata.registry("attribute", (1, 21, 4))  # renamed from generic.* in 1.21.2
    assert "generic.max_health" in gamedata.registry("attribute", (1, 21, 1))
    assert gamedata.block_states("oak_stairs", (1, 20, 0))["half"] == ("top", "bottom")
    assert gamedata.block_states("stone", (1, 20, 0)) == {}
    assert gamedata.block_states("no_such_block", (1, 20, 0)) is None
    # minecraft-data's defaultState, read through its state ids (StateDefinition's order)
    assert gamedata.default_state("minecraft:oak_stairs", (1, 20, 0)) == {
        "facing": "north", "half": "bottom", "shape": "straight", "waterlogged": "false"}
    assert gamedata.default_state("sea_pickle", (1, 13, 0)) == {"pickles": "1", "waterlogged": "true"}
    assert gamedata.default_state("stone", (1, 20, 0)) == {} and gamedata.default_state("nope", (1, 20, 0)) is None
    # RedStoneWireBlock's default (every side none, power 0), from 26.1's data
    assert gamedata.default_state("redstone_wire", (26, 1, 0)) == {
        "east": "none", "north": "none", "power": "0", "south": "none", "west": "none"}
    # newer releases than the newest registry data fall back to it, flagged as not exact
    assert gamedata.registry_release((26, 2, 0)) == ((26, 1, 0), False)
    assert gamedata.registry_release((1, 21, 7)) == ((1, 21, 6), False)
    assert gamedata.registry_release((1, 21, 11)) == ((1, 21, 11), True)
    assert "copper_golem" in gamedata.registry("entity_type", (1, 21, 9))  # 25w31a
    assert "copper_golem" not in gamedata.registry("entity_type", (1, 21, 8))
    assert "mannequin" in gamedata.registry("entity_type", (1, 21, 11))


@pytest.fixture
def own_reports(tmp_path, monkeypatch):
    """A folder of the user's reports; the memory of reports read emptied before and after."""
    monkeypatch.setenv("DPEMU_GAMEDATA", str(tmp_path))
    gamedata._user_report.cache_clear()
    gamedata._UNREADABLE.clear()
    yield tmp_path
    gamedata._user_report.cache_clear()
    gamedata._UNREADABLE.clear()


def test_an_unreadable_report_is_named_and_the_shipped_data_stands_in(own_reports):
    folder = own_reports / "1.19.1"
    folder.mkdir()
    (folder / "commands.json").write_text('{"broken')
    (folder / "registries.json").write_text("[1]")  # JSON, but not the registries report's shape
    assert gamedata.tree_release((1, 19, 1)) == (1, 19, 4)  # the shipped tree, as without a report
    assert gamedata.registry_release((1, 19, 1)) == ((1, 19, 0), True)  # the shipped data (a hotfix of 1.19)
    problems = dict(gamedata.unreadable_reports((1, 19, 1)))
    assert set(problems) == {str(folder / "commands.json"), str(folder / "registries.json")}
    commands = problems[str(folder / "commands.json")]
    assert "unreadable game report" in commands and "Minecraft 1.19.1" in commands
    assert "-DbundlerMainClass=net.minecraft.data.Main -jar server.jar --reports" in commands
    assert "not the game's registries report" in problems[str(folder / "registries.json")]
    assert gamedata.unreadable_reports((1, 19, 2)) == []


def test_loading_for_a_release_with_an_unreadable_report_is_an_error_naming_it(own_reports, tmp_path_factory):
    from mcfunction_parser import load_packs

    (own_reports / "1.19.1").mkdir()
    (own_reports / "1.19.1" / "commands.json").write_text("not json")
    pack = tmp_path_factory.mktemp("pack")
    (pack / "pack.mcmeta").write_text('{"pack": {"pack_format": 10, "description": ""}}')
    (pack / "data" / "t" / "functions").mkdir(parents=True)
    (pack / "data" / "t" / "functions" / "f.mcfunction").write_text("gamemode flying\n")
    loaded = load_packs([pack], mc_version="1.19.1")
    messages = [(d.path, d.message) for d in loaded.errors]
    assert messages[0][0] == str(own_reports / "1.19.1" / "commands.json")
    assert "unreadable game report" in messages[0][1] and "--reports" in messages[0][1]
    # the function is still checked, with the shipped tree
    assert any(d.line == 1 and d.col == 10 and "game mode" in d.message for d in loaded.errors)


def test_the_26_1_hotfixes_gate_the_same_commands_as_26_1(tmp_path, monkeypatch):
    # 26.1.1 and 26.1.2 are hotfixes of 26.1 (Mojang's 26.1.2 post, 2026-04-09: a hotfix for "a
    # couple of critical issues", a spectator exploit among them; the three read data pack format
    # 101.1, see pack.versions), with no command or registry change listed in any source found: the
    # parser gates the same commands in them, with 26.1's tree
    # (their own minor release's: no stand-in note), and their registries are 26.1's, as their own
    # (gamedata.registry_release: a patch release reading its minor release's data pack format), so
    # an id missing from them is an error there as in 26.1.
    from mcfunction_parser.features import COMMANDS, command_problem

    monkeypatch.setenv("DPEMU_GAMEDATA", str(tmp_path))
    releases = [(26, 1, 0), (26, 1, 1), (26, 1, 2)]
    assert {RELEASE_FORMATS[v] for v in releases} == {RELEASE_FORMATS[(26, 1, 0)]}
    gated = [{name for name in COMMANDS if command_problem(name, v) is None} for v in releases]
    assert gated[0] == gated[1] == gated[2] and {"swing", "fetchprofile"} <= gated[0]
    assert all(gamedata.tree_release(v) == (26, 1, 0) and gamedata.stand_in(v) is None for v in releases)
    assert [gamedata.registry_release(v) for v in releases] == [((26, 1, 0), True)] * 3
    for version in releases:
        _, diagnostics = parse_function("give @s no_such_item\n", "f.mcfunction", "t:f", version)
        assert [d.severity for d in diagnostics] == ["error"], version


def test_a_patch_release_reads_its_minor_releases_registries_when_its_format_is_the_same():
    # gamedata.registry_release: a release without registries of its own takes the newest before it;
    # they are its own when that release is of the same minor release and reads the same data pack
    # format (pack.versions' table, from the game jars' version.json): the hotfixes 1.14.2, 1.19.1,
    # 26.1.1 and 26.1.2. 1.21.2 (the bundles drop, format 57 after 48) and 1.21.7 (the Lava Chicken
    # music disc, format 81 after 80) changed the game's data: another release's, a warning per id;
    # so is 26.2 against 26.1's.
    exact = {version: gamedata.registry_release(version)
             for version in [(1, 14, 2), (1, 19, 1), (26, 1, 1), (26, 1, 2), (1, 21, 2), (1, 21, 7), (26, 2, 0)]}
    assert exact == {(1, 14, 2): ((1, 14, 1), True), (1, 19, 1): ((1, 19, 0), True),
                     (26, 1, 1): ((26, 1, 0), True), (26, 1, 2): ((26, 1, 0), True),
                     (1, 21, 2): ((1, 21, 1), False), (1, 21, 7): ((1, 21, 6), False),
                     (26, 2, 0): ((26, 1, 0), False)}
    _, diagnostics = parse_function("give @s no_such_item\n", "f.mcfunction", "t:f", (1, 21, 7))
    assert [d.severity for d in diagnostics] == ["warning"]


@pytest.mark.parametrize("version, ok", [((1, 21, 1), True), ((1, 21, 8), True), ((1, 21, 9), False)])
def test_setworldspawn_takes_an_angle_until_1_21_9(version, ok):
    # SetWorldSpawnCommand: ``<pos> [<angle>]`` until 1.21.8, ``<pos> [<rotation>]`` from 1.21.9; a
    # 1.21.1 pack is checked against 1.21.1's own tree, not a later one's
    _, diagnostics = parse_function("setworldspawn ~ ~ ~ 90\n", "f.mcfunction", "t:f", version)
    assert (not [d for d in diagnostics if d.severity == "error"]) is ok, diagnostics


def test_attribute_registries_follow_the_game_where_minecraft_data_lags():
    # minecraft-data's attribute lists of 1.16 - 1.20.6 are one copy of 1.16's (build.py's
    # _ATTRIBUTE_CHANGES): Attributes.java has generic.max_absorption from 1.20.2, and from 1.20.5
    # scale, step_height, the player's interaction ranges and generic.jump_strength for
    # horse.jump_strength
    def attributes(version):
        return gamedata.registry("attribute", version)

    assert "generic.max_absorption" not in attributes((1, 20, 1))
    assert "generic.max_absorption" in attributes((1, 20, 2)) and "generic.scale" not in attributes((1, 20, 4))
    assert {"generic.scale", "generic.step_height", "player.block_interaction_range",
            "generic.jump_strength"} <= attributes((1, 20, 5)) == attributes((1, 20, 6))
    assert "horse.jump_strength" in attributes((1, 20, 4)) and "horse.jump_strength" not in attributes((1, 20, 5))
    # a 1.20.6 pack's scale is no false error
    _, diagnostics = parse_function("attribute @s generic.scale base set 2\n", "f.mcfunction", "t:f", (1, 20, 6))
    assert not diagnostics


def test_language_is_the_releases_own_or_the_newest_before():
    # minecraft-data's language.json per release (the game's en_us.json), shipped as changes from
    # release to release: netherite's strings come with 1.16, 1.21.2 (no file of its own) reads
    # 1.21.1's, nothing before 1.13
    assert "item.minecraft.netherite_ingot" not in gamedata.language((1, 15, 2))
    assert gamedata.language((1, 16, 0))["item.minecraft.netherite_ingot"] == "Netherite Ingot"
    assert gamedata.language((1, 21, 2)) == gamedata.language((1, 21, 1))
    assert gamedata.language((1, 12, 2)) == {}
    assert gamedata.language((26, 1, 0))["chat.type.text"] == "<%s> %s"
