"""What setblock and fill do to the block they replace, on both backends.

Sources (decompiled 1.21, and 1.21.5 - 1.21.10 where they changed it):
server/commands/SetBlockCommand.java (setBlock: ``keep`` tests for air first; ``destroy`` runs Level.destroyBlock(pos, true) and places nothing when both the old and the
new block are air, still a success; the other modes run Clearable.tryClear on the block entity
before BlockInput.place, which fails on the same state), server/commands/FillCommand.java
(fillBlocks: the mode's filter, DESTROY breaking the block, then tryClear and place; a position
counts only when its block changed), world/level/Level.java (destroyBlock: nothing on air, else
Block.dropResources with no tool and no entity, then the fluid's block), world/Clearable.java and
its implementers (ChestBlockEntity and the other Containers: clearContent empties the items).
From 1.21.5 on, both place with UPDATE_SKIP_BLOCK_ENTITY_SIDEEFFECTS (flags 2 | 256) instead of
clearing, ``strict`` with 816 (no onPlace, known shape) and no updateNeighboursOnBlockSet, fill's
mode takes a filter before it, and a position its DESTROY affector broke counts even when nothing
could be placed there.
"""
from __future__ import annotations

import json

from tests.backends.programs import write_pack
from tests.backends.test_dimensions import SETUP, run_both, score

CHEST = 'chest{Items:[{Slot:0b,id:"minecraft:diamond",count:3}]}'
STONE_TABLE = {"pools": [{"rolls": 1, "entries": [{"type": "item", "name": "minecraft:cobblestone"}]}]}


def _run(tmp_path, lines: list[tuple[str, str]], setup: str = "", pack_format: int = 48,
         tables: tuple[str, ...] = ("stone",)):
    main = setup + "".join(f"execute store result score {holder} v run {command}\n" for holder, command in lines)
    root = write_pack(tmp_path / "pack", {"t:main": SETUP + main}, pack_format=pack_format)
    for block in tables:  # the game's own tables, as a pack may give them
        table = root / f"data/minecraft/loot_table/blocks/{block}.json"
        table.parent.mkdir(parents=True, exist_ok=True)
        table.write_text(json.dumps(STONE_TABLE))
    return run_both(root)


def _items(emu, name: str) -> int:
    return sum(int(e.data["Item"]["count"]) for e in emu.state.entities.entities
               if e.type == "minecraft:item" and e.data["Item"]["id"] == name)


def test_replacing_a_chest_by_the_same_chest_fails_and_empties_it(tmp_path):
    emu = _run(tmp_path, [("#same", "setblock 0 0 0 chest"),
                          ("#items", "data get block 0 0 0 Items"),
                          ("#other", f"setblock 1 0 0 {CHEST}"),
                          ("#stone", "setblock 1 0 0 stone")],
               f"setblock 0 0 0 {CHEST}\n")
    assert [score(emu, h) for h in ("#same", "#other", "#stone")] == [0, 1, 1]
    assert emu.state.blocks.entity((0, 0, 0))["Items"] == []  # cleared though the placing failed
    assert not emu.entities("@e[type=item]")  # replace drops nothing: the contents were cleared first


def test_destroy_drops_the_blocks_loot_and_keeps_the_games_results(tmp_path):
    emu = _run(tmp_path, [("#destroyed", "setblock 0 0 0 air destroy"),
                          ("#air_on_air", "setblock 0 0 0 air destroy"),  # nothing placed: a success
                          ("#replace_air", "setblock 0 0 0 air"),  # the same state: a failure
                          ("#fill_air", "fill 1 0 0 2 0 0 air destroy"),  # broken, none placed: fails
                          ("#fill_stone", "fill 3 0 0 4 0 0 stone destroy"),  # broken, then placed again
                          ("#keep", "setblock 3 0 0 dirt keep")],
               "setblock 0 0 0 stone\nfill 1 0 0 4 0 0 stone\n")
    assert [score(emu, h) for h in ("#destroyed", "#air_on_air", "#replace_air", "#fill_air", "#fill_stone",
                                    "#keep")] == [1, 1, 0, 0, 2, 0]
    assert _items(emu, "minecraft:cobblestone") == 5  # one per stone broken: 0, 1, 2, 3 and 4
    block = lambda pos: emu.state.blocks.get(pos).id  # noqa: E731
    assert block((1, 0, 0)) == "minecraft:air" and block((3, 0, 0)) == "minecraft:stone"


def test_no_drops_when_the_rule_says_so(tmp_path):
    emu = _run(tmp_path, [("#destroyed", "setblock 0 0 0 air destroy")],
               "setblock 0 0 0 stone\ngamerule doTileDrops false\n")
    assert score(emu, "#destroyed") == 1 and not emu.entities("@e[type=item]")


def test_a_destroyed_container_spilling_its_contents_is_not_modelled(tmp_path):
    emu = _run(tmp_path, [], f"setblock 0 0 0 {CHEST}\nsetblock 0 0 0 air destroy\n")
    assert any(d.unmodelled and "spills" in d.message for d in emu.diagnostics)


def test_from_1_21_5_the_contents_stay_and_a_destroyed_block_counts(tmp_path):
    emu = _run(tmp_path, [("#same", "setblock 0 0 0 chest"),
                          ("#fill_air", "fill 1 0 0 2 0 0 air destroy"),  # broken, none placed: 2 all the same
                          ("#filtered", "fill 3 0 0 6 0 0 dirt replace stone destroy")],
               f"setblock 0 0 0 {CHEST}\nfill 1 0 0 4 0 0 stone\n", pack_format=71)
    assert [score(emu, h) for h in ("#same", "#fill_air", "#filtered")] == [0, 2, 2]
    assert len(emu.state.blocks.entity((0, 0, 0))["Items"]) == 1  # no Clearable.tryClear any more
    assert _items(emu, "minecraft:cobblestone") == 4  # 1, 2, 3 and 4: the filter kept 5 and 6 (air) out
    assert [emu.state.blocks.get((x, 0, 0)).id for x in (3, 4, 5, 6)] == ["minecraft:dirt"] * 2 + ["minecraft:air"] * 2


def test_strict_places_without_the_blocks_own_reaction(tmp_path):
    # a rail placed beside another joins it (BaseRailBlock.onPlace); strict skips onPlace
    emu = _run(tmp_path, [("#plain", "setblock 1 0 0 rail"), ("#strict", "setblock 1 0 5 rail strict")],
               "fill 0 -1 0 1 -1 5 stone\nsetblock 0 0 0 rail\nsetblock 0 0 5 rail\n", pack_format=71)
    assert [score(emu, h) for h in ("#plain", "#strict")] == [1, 1]
    shape = lambda pos: dict(emu.state.blocks.get(pos).properties)["shape"]  # noqa: E731
    assert shape((1, 0, 0)) == "east_west" and shape((1, 0, 5)) == "north_south"


def _orbs(emu) -> list[int]:
    return sorted(int(e.data["Value"]) for e in emu.state.entities.entities if e.type == "minecraft:experience_orb")


def test_destroyed_ores_spawners_and_sculk_drop_their_experience(tmp_path):
    """BlockState.spawnAfterBreak with dropExperience (Level.destroyBlock -> Block.dropResources):
    DropExperienceBlock's IntProvider (Blocks: diamond ore UniformInt.of(3, 7), iron ore
    ConstantInt.of(0)), SculkCatalystBlock's ConstantInt.of(5), SpawnerBlock's 15 + nextInt(15) +
    nextInt(15); ExperienceOrb.award splits the points by getExperienceValue (3 -> 3, 5 -> 3 + 1 + 1,
    7 -> 7)."""
    emu = _run(tmp_path, [("#ore", "setblock 0 0 0 air destroy"), ("#iron", "setblock 1 0 0 air destroy"),
                          ("#catalyst", "setblock 2 0 0 air destroy")],
               "setblock 0 0 0 diamond_ore\nsetblock 1 0 0 iron_ore\nsetblock 2 0 0 sculk_catalyst\n",
               tables=("diamond_ore", "iron_ore", "sculk_catalyst"))
    assert [score(emu, h) for h in ("#ore", "#iron", "#catalyst")] == [1, 1, 1]
    orbs = _orbs(emu)
    assert sum(orbs) - 5 in range(3, 8)  # the ore's 3 - 7, the catalyst's 5, the iron ore's none
    assert all(value in (1, 3, 7) for value in orbs)
    # the spawner's table is the game's noDrop() (VanillaBlockLoot), known without its data
    spawner = _run(tmp_path / "spawner", [("#spawner", "setblock 0 0 0 air destroy")], "setblock 0 0 0 spawner\n")
    assert sum(_orbs(spawner)) in range(15, 44) and not spawner.entities("@e[type=item]") and not spawner.diagnostics
    positions = {tuple(e["pos"]) for e in spawner.entities("@e[type=experience_orb]")}
    assert positions == {(0.5, 0.5, 0.5)}  # Vec3.atCenterOf(pos)


def test_no_experience_when_the_rule_says_so(tmp_path):
    emu = _run(tmp_path, [("#spawner", "setblock 0 0 0 air destroy")],
               "setblock 0 0 0 spawner\ngamerule doTileDrops false\n")  # Block.popExperience reads it
    assert score(emu, "#spawner") == 1 and _orbs(emu) == []
