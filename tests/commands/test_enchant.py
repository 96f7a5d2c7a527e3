"""Enchantment definition files (1.21+) and the ``enchant`` command with the packs' enchantments.

Sources (decompiled 1.21): world/item/enchantment/Enchantment.java (DIRECT_CODEC,
EnchantmentDefinition.CODEC: weight 1-1024, max_level 1-255; canEnchant; areCompatible),
server/commands/EnchantCommand.java (enchant: the level check, a single target's errors, the
count), EnchantmentHelper.java (isEnchantmentCompatible, getComponentType), ItemEnchantments.java
(Mutable.upgrade: the higher level).
"""
import json

import pytest

from emulator import Emulator
from tests.conftest import write_pack

COSTS = {"min_cost": {"base": 1, "per_level_above_first": 1}, "max_cost": {"base": 5, "per_level_above_first": 1},
         "anvil_cost": 1, "weight": 1}
FILES = {
    "demo/enchantment/zap.json": json.dumps({"description": "Zap", "supported_items": "#demo:zappable", "max_level": 3,
                                             "slots": ["mainhand"], "exclusive_set": "demo:calm", **COSTS}),
    "demo/enchantment/calm.json": json.dumps({"description": "Calm", "supported_items": ["stick", "blaze_rod"],
                                              "max_level": 1, "slots": ["hand"], **COSTS}),
    "demo/enchantment/glow.json": json.dumps({"description": "Glow", "supported_items": "stick", "max_level": 1,
                                              "slots": ["hand"], "effects": {"minecraft:tick": []}, **COSTS}),
    "demo/enchantment/bad.json": json.dumps({"description": "Bad", "supported_items": "stick", "max_level": 256,
                                             "slots": ["hand"], **COSTS}),
    "demo/tags/item/zappable.json": json.dumps({"values": ["stick"]}),
    "demo/function/hold.mcfunction": 'summon armor_stand 0 0 0 {Tags:["a"],HandItems:[{id:"minecraft:stick",count:1},{}]}\n'
                                     'summon armor_stand 0 0 0 {Tags:["b"],HandItems:[{id:"minecraft:apple",count:1},{}]}\n'
                                     'summon armor_stand 0 0 0 {Tags:["c"]}\nsummon marker 0 0 0 {Tags:["m"]}\n',
}


COMMANDS = ["enchant @e[tag=a] demo:zap 2", "enchant @e[tag=a] demo:zap 4", "enchant @e[tag=a] demo:zap 3",
            "enchant @e[tag=a] demo:calm", "enchant @e[tag=b] demo:zap", "enchant @e[tag=c] demo:zap",
            "enchant @e[tag=m] demo:zap", "enchant @e[type=!player] demo:calm", "enchant @e[tag=a] demo:glow",
            "enchant @e[tag=a] minecraft:sharpness"]


def emulator(tmp_path, backend):
    emu = Emulator(backend=backend)
    files = {**FILES, **{f"demo/function/run{i}.mcfunction": f"execute store result storage t:r v int 1 run {c}\n"
                         for i, c in enumerate(COMMANDS)}}
    emu.load([write_pack(tmp_path / "pack", files)])  # pack format 48: 1.21
    emu.call("demo:hold")
    return emu


def result(emu, command: str):
    """The command's result (0 when it failed) and the diagnostics it raised."""
    seen = len(emu.diagnostics)
    emu.call(f"demo:run{COMMANDS.index(command)}")
    return int(emu.state.storage["t:r"]["v"]), [d.message for d in emu.diagnostics[seen:]]


def levels(emu, tag: str):
    hand = emu.state.entities.by_holder(emu.entities(f"@e[tag={tag}]")[0]["uuid"]).data["HandItems"][0]
    return {k: int(v) for k, v in hand.get("components", {}).get("minecraft:enchantments", {}).get("levels", {}).items()}


def test_a_file_that_does_not_decode_is_an_error_at_its_field(tmp_path):
    emu = Emulator()
    emu.load([write_pack(tmp_path / "pack", FILES)])
    errors = [d.format() for d in emu.load_diagnostics if d.severity == "error"]
    assert len(errors) == 1 and 'enchantment demo:bad fails to load: "max_level" must be an integer from 1 to 255' in errors[0]
    assert set(emu.packs.enchantments) == {"demo:zap", "demo:calm", "demo:glow"}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_enchant_with_a_packs_enchantments(tmp_path, backend):
    emu = emulator(tmp_path, backend)
    assert result(emu, "enchant @e[tag=a] demo:zap 2") == (1, [])
    assert levels(emu, "a") == {"demo:zap": 2}
    # the level is checked first; the same enchantment again, or one in its exclusive set, does not fit
    assert result(emu, "enchant @e[tag=a] demo:zap 4")[0] == 0
    assert result(emu, "enchant @e[tag=a] demo:zap 3")[0] == 0
    assert result(emu, "enchant @e[tag=a] demo:calm")[0] == 0
    assert levels(emu, "a") == {"demo:zap": 2}
    # not supported (an apple), no item, not living: nothing changes, and the command fails
    assert result(emu, "enchant @e[tag=b] demo:zap")[0] == 0
    assert result(emu, "enchant @e[tag=c] demo:zap")[0] == 0
    assert result(emu, "enchant @e[tag=m] demo:zap")[0] == 0
    # several targets: the ones that can take it count, the others are skipped
    assert result(emu, "enchant @e[type=!player] demo:calm") == (0, [])  # a has zap, b an apple
    assert result(emu, "enchant @e[tag=a] demo:glow") == (1, ["the effects of enchantment demo:glow are not modelled"])


def test_the_games_own_enchantments_are_not_modelled(tmp_path):
    emu = emulator(tmp_path, "python")
    value, messages = result(emu, "enchant @e[tag=a] minecraft:sharpness")
    assert value == 0 and messages == ["not modelled: the game's own enchantment minecraft:sharpness (its definition "
                                       "is not read here)"]
