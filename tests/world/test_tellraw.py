"""``tellraw``: receivers and resolved text components, on both backends.

Source (decompiled 1.21): server/commands/TellRawCommand.java (EntityArgument.getPlayers: no
player fails; the result is the number of players), network/chat/ComponentUtils.updateForEntity,
contents/ScoreContents, SelectorContents, NbtContents.
"""
from __future__ import annotations

import json

import pytest

from tests.world.world_emulator import emulator

BACKENDS = ["python", "numba"]


def plain(text: str) -> str:
    value = json.loads(text)
    if isinstance(value, list):
        return "".join(plain(json.dumps(v)) for v in value)
    if isinstance(value, dict):
        return str(value.get("text", "")) + "".join(plain(json.dumps(v)) for v in value.get("extra", []))
    return str(value)


@pytest.mark.parametrize("backend", BACKENDS)
def test_tellraw_needs_a_player_and_counts_them(tmp_path, backend):
    emu = emulator(tmp_path, backend, {"t:main": 'execute store result score #n o run tellraw @a {"text":"hi"}'})
    emu.call("t:main")
    assert (emu.score("#n", "o"), [e.text for e in emu.log]) == (0, [])
    emu.add_player("Alex")
    emu.add_player("Steve")
    emu.call("t:main")
    assert (emu.score("#n", "o"), [e.text for e in emu.log]) == (2, ['{"text":"hi"}'])  # as written


@pytest.mark.parametrize("backend", BACKENDS)
def test_score_selector_and_nbt_parts_are_resolved(tmp_path, backend):
    emu = emulator(tmp_path, backend, {"t:main": "\n".join([
        'summon pig 0 0 0 {Tags:["b"]}', 'summon pig 0 0 0 {CustomName:\'"Babe"\'}',
        "scoreboard players set @e[tag=b] o 3", "scoreboard players set Alex o 11",
        "data modify storage t:s v set value 5b",
        'execute as @e[tag=b] run tellraw @a [{"text":"ball "},{"score":{"name":"@s","objective":"o"}},'
        '{"text":" is pocketed"}]',
        'tellraw @a {"text":"pigs: ","extra":[{"selector":"@e[type=pig]"}]}',
        'tellraw @a [{"score":{"name":"*","objective":"o"}},{"text":" "},{"nbt":"v","storage":"t:s"},'
        '{"score":{"name":"#unset","objective":"o"}}]',
    ])})
    emu.add_player("Alex")
    emu.call("t:main")
    assert [plain(e.text) for e in emu.log] == ["ball 3 is pocketed", "pigs: Pig, Babe", "11 5b"]


@pytest.mark.parametrize("backend", ["python", pytest.param("numba", marks=pytest.mark.xfail(
    strict=True, reason="the VM's OP_LOG decides success before the host resolves the text"))])
def test_a_score_selector_must_find_one_entity(tmp_path, backend):
    emu = emulator(tmp_path, backend, {"t:main": "summon pig\nsummon pig\n"
                   'execute store success score #ok o run tellraw @a {"score":{"name":"@e[type=pig]","objective":"o"}}'})
    emu.add_player("Alex")
    emu.call("t:main")
    assert (emu.score("#ok", "o"), emu.log) == (0, [])


@pytest.mark.parametrize("backend", BACKENDS)
def test_say_replaces_its_selectors_by_names(tmp_path, backend):
    # MessageArgument: each selector becomes the display names it finds, joined with ", "
    emu = emulator(tmp_path, backend, {"t:main": "summon pig\nsummon cow 0 0 0 {CustomName:'\"Daisy\"'}\n"
                                       "say found @e[type=!player] and @e[tag=none] at @s"})
    emu.call("t:main")
    assert [e.text for e in emu.log] == ["[Server] found Pig, Daisy and  at "]


@pytest.mark.parametrize("backend", BACKENDS)
def test_each_player_gets_the_text_resolved_for_them(tmp_path, backend):
    # TellRawCommand: sendSystemMessage(ComponentUtils.updateForEntity(source, text, player)) per
    # player; a `*` score is the receiver's: one log entry per distinct text, with its receivers
    emu = emulator(tmp_path, backend, {"t:main": "scoreboard players set Alex o 11\nscoreboard players set Steve o 4\n"
                                       "scoreboard players set Sam o 4\n"
                                       'tellraw @a [{"text":"you have "},{"score":{"name":"*","objective":"o"}}]\n'
                                       'tellraw @a[name=!Sam] "plain"'})
    uuid = {emu.add_player(name): name for name in ("Alex", "Steve", "Sam")}
    emu.call("t:main")
    assert [(plain(e.text), [uuid[r] for r in e.receivers]) for e in emu.log] == [
        ("you have 11", ["Alex"]), ("you have 4", ["Steve", "Sam"]), ("plain", ["Alex", "Steve"])]


@pytest.mark.parametrize("backend", BACKENDS)
def test_nbt_interpret_reads_each_value_as_a_component(tmp_path, backend):
    """NbtContents.resolve with interpret: before 1.21.5 each value's string is parsed as JSON and
    resolved in turn (a score inside it too); the values join with the separator."""
    emu = emulator(tmp_path, backend, {"t:main": "\n".join([
        "scoreboard players set Alex o 7",
        'data modify storage t:s names set value [\'{"text":"a"}\',\'{"score":{"name":"Alex","objective":"o"}}\']',
        'tellraw @a {"nbt":"names[]","storage":"t:s","interpret":true,"separator":"+"}',
        'tellraw @a {"nbt":"names[]","storage":"t:s"}',
    ])})
    emu.add_player("Alex")
    emu.call("t:main")
    assert [plain(e.text) for e in emu.log][0] == "a+7"
    assert plain(emu.log[1].text) == '{"text":"a"}, {"score":{"name":"Alex","objective":"o"}}'


def test_nbt_interpret_takes_the_tag_itself_from_1_21_5(tmp_path):
    """From 1.21.5 ComponentSerialization.CODEC reads the tag: a compound is a component, a string
    tag is plain text (not parsed as JSON)."""
    emu = emulator(tmp_path, "python", {"t:main": "\n".join([
        "data modify storage t:s v set value [{text:\"x\",extra:[\"y\"]}, {text:\"w\"}]",
        "data modify storage t:s s set value '{\"text\":\"z\"}'",
        'tellraw @a [{"nbt":"v[]","storage":"t:s","interpret":true},{"nbt":"s","storage":"t:s","interpret":true}]',
    ])})
    emu.state.version = (1, 21, 5)
    emu.add_player("Alex")
    emu.call("t:main")
    assert plain(emu.log[0].text) == 'xy, w{"text":"z"}'


@pytest.mark.parametrize("text, plain", [
    ('{"text":"a","extra":[{"text":"b"}]}', "ab"),  # JSON
    ('{text: "No log entries…", color: "gray"}', "No log entries…"),  # SNBT, as 1.21.5+ commands write it
    ("['x', {text: 'y'}]", "xy"),
    ("just words", "just words"),
])
def test_plain_text_reads_json_and_snbt_components(text, plain):
    from emulator.world.text import plain_text
    assert plain_text(text) == plain


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_selector_part_is_each_entitys_display_name(tmp_path, backend):
    """SelectorContents.resolve: ComponentUtils.formatList of Entity.getDisplayName: one name as it
    is, with the entity's UUID to insert and a show_entity hover (a player: its name to insert and
    a /tell suggestion, Player.decorateDisplayNameComponent), several joined by a grey ", "; the
    written style wins (MutableComponent.withStyle)."""
    emu = emulator(tmp_path, backend, {"t:main": "\n".join([
        'summon pig 0 0 0 {UUID:[I;1,2,3,4],CustomName:\'"Babe"\'}',
        'tellraw @a {"selector":"@e[type=pig]","color":"red"}',
        'tellraw @a {"selector":"@a"}',
        'summon pig',
        'tellraw @a {"selector":"@e[type=pig]"}',
    ])})
    emu.add_player("Alex")
    emu.call("t:main")
    babe, alex, both = (json.loads(e.text) for e in emu.log)
    uuid = "00000001-0000-0002-0000-000300000004"
    assert babe == {"text": "Babe", "insertion": uuid, "color": "red", "hoverEvent": {
        "action": "show_entity", "contents": {"type": "minecraft:pig", "id": uuid, "name": {"text": "Babe"}}}}
    assert alex["insertion"] == "Alex" and alex["clickEvent"] == {"action": "suggest_command", "value": "/tell Alex "}
    assert both["text"] == "" and [plain(json.dumps(p)) for p in both["extra"]] == ["Babe", ", ", "Pig"]
    assert both["extra"][1] == {"text": ", ", "color": "gray"}



@pytest.mark.parametrize("pack_format, printed", [
    # StringTagVisitor.visitCompound sorts the keys (Collections.sort before 1.21.5,
    # Entry.comparingByKey from it: String.compareTo); handleEscape writes a key bare when it matches
    # SIMPLE_VALUE [A-Za-z0-9._+-]+ before 1.21.5, from 1.21.5 when it matches UNQUOTED_KEY_MATCH
    # [A-Za-z._]+[A-Za-z0-9._+-]* and is not true or false; visitFloat/visitDouble append
    # Float.toString/Double.toString (decompiled 1.21.1 and 1.21.11 nbt/StringTagVisitor)
    (48, '{1x:1b,C:3,a:2,"a b":{x:64.0d,y:1.0E-5f},b:[0.1f,1.5E-4f],true:0b}'),
    (71, '{"1x":1b,C:3,a:2,"a b":{x:64.0d,y:1.0E-5f},b:[0.1f,1.5E-4f],"true":0b}'),
])
def test_compounds_print_as_the_game_prints_them(tmp_path, pack_format, printed):
    # a text component's nbt (NbtContents: Tag.getAsString) and a macro argument (MacroFunction:
    # Tag.toString) print the same
    emu = emulator(tmp_path, "python", {
        "t:main": "data modify storage t:s v set value {b:[0.1f,1.5e-4f],a:2,C:3,'a b':{y:1e-5f,x:64d},1x:1b,true:0b}\n"
                  'tellraw @a {"nbt":"v","storage":"t:s"}\n'
                  "function t:say with storage t:s",
        "t:say": "$say $(v)"}, pack_format=pack_format)
    emu.add_player("Alex")
    emu.call("t:main")
    assert [plain(emu.log[0].text), emu.log[1].text] == [printed, "[Server] " + printed]
