"""Dummies mining with tools (emulator.world.tools): whether the block drops
(Player.hasCorrectToolForDrops -> Tool.isCorrectForDrops with the vanilla tools' rules,
ToolMaterial.applyToolProperties: denied by #incorrect_for_<tier>_tool, mined and dropped by
#mineable/<tool>; before 1.20.5 DiggerItem.isCorrectToolForDrops with the needs_<tier>_tool tags)
and what it costs the tool (ItemStack.mineBlock: used:<item>; Item.mineBlock: damage_per_block
unless the block breaks instantly; ItemStack.hurtAndBreak: broken:<item>).
PackTest's mine breaks the block at once (DummyCommand.mineBlock -> ServerPlayerGameMode.destroyBlock),
so the mining speed is never seen."""
import json

import pytest

from tests.testing.test_dummy_hands import run


def _tag(values, replace=True):
    return json.dumps({"replace": replace, "values": values})


def _table(item):
    return json.dumps({"pools": [{"rolls": 1, "entries": [{"type": "minecraft:item", "name": item}]}]})


TAGS = {  # the game's tags are not shipped: the tests give the ones they read (replace: fully known)
    "minecraft/tags/block/mineable/pickaxe.json": _tag(["minecraft:stone", "minecraft:obsidian", "minecraft:torch"]),
    "minecraft/tags/block/incorrect_for_wooden_tool.json": _tag(["minecraft:obsidian"]),
    "minecraft/tags/block/incorrect_for_diamond_tool.json": _tag([]),
    "minecraft/loot_table/blocks/stone.json": _table("minecraft:cobblestone"),
    "minecraft/loot_table/blocks/obsidian.json": _table("minecraft:obsidian"),
    "minecraft/loot_table/blocks/torch.json": _table("minecraft:torch"),
}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_pickaxe_harvests_what_its_tier_allows_and_wears(tmp_path, backend):
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add used minecraft.used:minecraft.wooden_pickaxe\n"
        "scoreboard objectives add broke minecraft.broken:minecraft.wooden_pickaxe\n"
        "setblock ~2 ~ ~ stone\nsetblock ~2 ~1 ~ obsidian\nsetblock ~2 ~2 ~ torch\n"
        "give @s wooden_pickaxe[damage=56]\n"
        "dummy @s mine ~2 ~ ~\n"
        "assert entity @e[type=item,nbt={Item:{id:\"minecraft:cobblestone\"}}]\n"
        "assert items entity @s weapon.mainhand wooden_pickaxe[damage=57]\n"
        "assert score @s used matches 1\n"
        "dummy @s mine ~2 ~2 ~\n"                       # a torch breaks instantly: no wear
        "assert items entity @s weapon.mainhand wooden_pickaxe[damage=57]\n"
        "assert score @s used matches 2\n"
        "dummy @s mine ~2 ~1 ~\n"                       # wood cannot harvest obsidian
        "assert block ~2 ~1 ~ air\n"
        "assert not entity @e[type=item,nbt={Item:{id:\"minecraft:obsidian\"}}]\n"
        "assert items entity @s weapon.mainhand wooden_pickaxe[damage=58]\n"
        "setblock ~2 ~1 ~ stone\n"
        "dummy @s mine ~2 ~1 ~\n"                       # the last point of durability: it breaks
        "assert not items entity @s weapon.mainhand *\n"
        "assert score @s broke matches 1\n"), files=TAGS, backend=backend)
    assert result.status == "passed", result.report()


def test_a_creative_dummy_wears_no_tool_and_a_patched_tool_component_decides(tmp_path):
    """ServerPlayerGameMode.destroyBlock returns before mineBlock for a creative player; a stick with
    a tool component whose rule drops stone harvests it (Tool.isCorrectForDrops)."""
    result = run(tmp_path, "# @dummy\n" + (
        "gamemode creative @s\n"
        "setblock ~2 ~ ~ stone\n"
        "give @s diamond_pickaxe\n"
        "dummy @s mine ~2 ~ ~\n"
        "assert items entity @s weapon.mainhand diamond_pickaxe[damage=0]\n"
        "assert not entity @e[type=item]\n"
        "gamemode survival @s\n"
        "item replace entity @s weapon.mainhand with stick[tool={rules:[{blocks:\"minecraft:stone\","
        "correct_for_drops:true}],damage_per_block:0}]\n"
        "setblock ~2 ~ ~ stone\n"
        "dummy @s mine ~2 ~ ~\n"
        "assert entity @e[type=item,nbt={Item:{id:\"minecraft:cobblestone\"}}]\n"
        "assert items entity @s weapon.mainhand stick\n"), files=TAGS)
    assert result.status == "passed", result.report()


def test_before_1_20_5_the_tier_and_needs_tags_decide(tmp_path):
    """1.20.4 DiggerItem.isCorrectToolForDrops: a tier below 3 cannot harvest #needs_diamond_tool;
    DiggerItem.mineBlock: hurtAndBreak(1) into the tag's Damage."""
    files = {"minecraft/tags/blocks/mineable/pickaxe.json": _tag(["minecraft:obsidian"]),
             "minecraft/tags/blocks/needs_diamond_tool.json": _tag(["minecraft:obsidian"]),
             "minecraft/tags/blocks/needs_iron_tool.json": _tag([]),
             "minecraft/tags/blocks/needs_stone_tool.json": _tag([]),
             "minecraft/loot_tables/blocks/obsidian.json": _table("minecraft:obsidian")}
    result = run(tmp_path, "# @dummy\n" + (
        "setblock ~2 ~ ~ obsidian\nsetblock ~2 ~1 ~ obsidian\n"
        "give @s iron_pickaxe\n"
        "dummy @s mine ~2 ~ ~\n"
        "assert not entity @e[type=item]\n"
        "assert data entity @s SelectedItem.tag{Damage:1}\n"
        "item replace entity @s weapon.mainhand with diamond_pickaxe\n"
        "dummy @s mine ~2 ~1 ~\n"
        "assert entity @e[type=item]\n"), pack_format=26, files=files)
    assert result.status == "passed", result.report()


WORN = {  # item_durability_changed counted by a reward that revokes the advancement to hear the next
    **TAGS,
    "demo/advancement/worn.json": json.dumps({"criteria": {"w": {"trigger": "minecraft:item_durability_changed",
        "conditions": {"item": {"items": "minecraft:diamond_pickaxe"}, "delta": -1}}},
        "rewards": {"function": "demo:worn"}}),
    "demo/advancement/low.json": json.dumps({"criteria": {"w": {"trigger": "minecraft:item_durability_changed",
        "conditions": {"durability": {"max": 1555}}}}}),
    "demo/function/worn.mcfunction": "scoreboard players add @s worn 1\nadvancement revoke @s only demo:worn\n",
}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_unbreaking_spares_some_damage_and_each_point_taken_fires_item_durability_changed(tmp_path, backend):
    """ItemStack.hurtAndBreak: processDurabilityChange (Unbreaking III: each point spared with chance
    3/4, from the seeded random) before ItemDurabilityTrigger (delta: old damage - new; durability:
    what is left), which fires only for damage taken."""
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add worn dummy\n"
        "fill ~2 ~ ~ ~2 ~19 ~ stone\n"
        "give @s diamond_pickaxe[enchantments={levels:{\"minecraft:unbreaking\":3}}]\n"
        + "".join(f"dummy @s mine ~2 ~{y} ~\n" for y in range(19, -1, -1)) +
        "execute store result score #damage worn run data get entity @s SelectedItem.components.\"minecraft:damage\"\n"
        "assert score #damage worn matches 1..15\n"          # 20 blocks, about 5 points taken
        "assert score #damage worn = @s worn\n"
        "assert entity @s[advancements={demo:low=false}]\n"
        "item replace entity @s weapon.mainhand with diamond_pickaxe[damage=1554]\n"
        "setblock ~2 ~ ~ stone\ndummy @s mine ~2 ~ ~\n"
        "assert entity @s[advancements={demo:low=true}]\n"), pack_format=61, files=WORN, backend=backend)
    assert result.status == "passed", result.report()


def test_a_trident_and_a_mace_mine_as_tools_without_rules(tmp_path):
    """TridentItem / MaceItem.createToolProperties: Tool(no rules, speed 1, 2 damage a block): a
    block that needs a tool does not drop, the weapon wears by 2 unless the block breaks instantly."""
    result = run(tmp_path, "# @dummy\n" + (
        "setblock ~2 ~ ~ stone\nsetblock ~4 ~ ~ stone\nsetblock ~4 ~1 ~ torch\n"
        "give @s trident\n"
        "dummy @s mine ~2 ~ ~\n"
        "assert block ~2 ~ ~ air\n"
        "assert not entity @e[type=item]\n"
        "assert data entity @s SelectedItem.components{\"minecraft:damage\":2}\n"
        "item replace entity @s weapon.mainhand with mace\n"
        "dummy @s mine ~4 ~1 ~\n"
        "assert block ~4 ~1 ~ air\n"
        "assert not data entity @s SelectedItem.components.\"minecraft:damage\"\n"), pack_format=61, files=TAGS)
    assert result.status == "passed", result.report()
