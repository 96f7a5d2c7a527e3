"""What setblock and fill do to the block they replace, on both backends.

Sources (decompiled 1.21): server/commands/SetBlockCommand.java (setBlock: ``keep`` tests for air
first; ``destroy`` runs Level.destroyBlock(pos, true) and places nothing when both the old and the
new block are air, still a success; the other modes run Clearable.tryClear on the block entity
before BlockInput.place, which fails on the same state), server/commands/FillCommand.java
(fillBlocks: the mode's filter, DESTROY breaking the block, then tryClear and place; a position
counts only when its block changed), world/level/Level.java (destroyBlock: nothing on air, else
Block.dropResources with no tool and no entity, then the fluid's block), world/Clearable.java and
its implementers (ChestBlockEntity and the other Containers: clearContent empties the items).
"""
from __future__ import annotations

import json

from tests.backends.test_dimensions import pack, run_both, score

CHEST = 'chest{Items:[{Slot:0b,id:"minecraft:diamond",count:3}]}'
STONE_TABLE = {"pools": [{"rolls": 1, "entries": [{"type": "item", "name": "minecraft:cobblestone"}]}]}


def _run(tmp_path, lines: list[tuple[str, str]], setup: str = ""):
    main = setup + "".join(f"execute store success score {holder} v run {command}\n" for holder, command in lines)
    root = pack(tmp_path, main)
    table = root / "data/minecraft/loot_table/blocks/stone.json"  # the game's own table, as a pack may give it
    table.parent.mkdir(parents=True)
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
                                    "#keep")] == [1, 1, 0, 0, 1, 0]
    assert _items(emu, "minecraft:cobblestone") == 5  # one per stone broken: 0, 1, 2, 3 and 4
    assert emu.state.blocks.get((1, 0, 0)).id == "minecraft:air" and emu.state.blocks.get((3, 0, 0)).id == "minecraft:stone"


def test_no_drops_when_the_rule_says_so(tmp_path):
    emu = _run(tmp_path, [("#destroyed", "setblock 0 0 0 air destroy")],
               "setblock 0 0 0 stone\ngamerule doTileDrops false\n")
    assert score(emu, "#destroyed") == 1 and not emu.entities("@e[type=item]")


def test_a_destroyed_container_spilling_its_contents_is_not_modelled(tmp_path):
    emu = _run(tmp_path, [], f"setblock 0 0 0 {CHEST}\nsetblock 0 0 0 air destroy\n")
    assert any(d.unmodelled and "spills" in d.message for d in emu.diagnostics)
