"""``place template``: a pack's structure file placed by a command, as libraries place their
prefabs (PlaceCommand.placeTemplate, decompiled 1.21: the template from the structure manager, its
corner at the position or the source's block, StructureTemplate.placeInWorld, mirrored then
turned about it; "There is no template with id" and "Failed to place template" fail the command)."""
import pytest

from tests.testing.test_structures import BLOCKS, ENTITY, PALETTE, ints, nbt_file, results, structure, write

TEST = "\n".join([
    "scoreboard objectives add t dummy",
    # the same chest already there: cleared, replaced by a barrier, and the template's loaded
    "setblock ~5 ~1 ~ chest{Lock:\"old\",Items:[{Slot:0b,id:\"minecraft:stone\",count:1}]}",
    "place template demo:room ~3 ~ ~",
    "assert not block ~5 ~1 ~ chest{Items:[{}]}",
    "assert block ~3 ~ ~ stone",
    "assert block ~4 ~ ~ oak_stairs[facing=east]",
    "assert block ~5 ~1 ~ chest{Lock:\"key\"}",
    "assert entity @e[type=armor_stand,tag=from_template,x=4.5,y=2,z=0.5,distance=..0.001]",
    "execute positioned ~ ~4 ~ run place template demo:room",  # at the source's block
    "assert block ~ ~4 ~ stone",
    "execute store success score #missing t run place template demo:missing ~ ~ ~",
    "assert score #missing t matches 0",
    "execute store success score #empty t run place template demo:empty ~ ~ ~",
    "assert score #empty t matches 0",
])


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_place_template_puts_the_packs_structure_at_the_position(tmp_path, backend):
    empty = nbt_file({"size": ints(0, 0, 0), "palette": ("list", ("compound", [])),
                      "blocks": ("list", ("compound", [])), "entities": ("list", ("compound", []))})
    root = write(tmp_path, {"demo/structure/room.nbt": structure(BLOCKS, PALETTE, [ENTITY]),
                            "demo/structure/empty.nbt": empty,
                            "demo/test/place.mcfunction": TEST + "\n"})
    result = results(root, backend)["demo:place"]
    assert result.status == "passed", result.report()


TURNED = "\n".join([
    # StructureTemplate.transform about the corner: (x, z) -> (-z, x) a quarter turn clockwise; the
    # stairs' facing turned (HorizontalDirectionalBlock.rotate), the chest's default north too
    "place template demo:room ~3 ~ ~ clockwise_90",
    "assert block ~3 ~ ~ stone",
    "assert block ~3 ~ ~1 oak_stairs[facing=south]",
    "assert block ~3 ~1 ~2 chest[facing=east]{Lock:\"key\"}",
    # an entity's position about the far side of its block; its yaw by Entity.rotate
    "assert entity @e[type=armor_stand,tag=from_template,x=3.5,y=2,z=1.5,distance=..0.001,nbt={Rotation:[90.0f,0.0f]}]",
    "kill @e[type=armor_stand]",
    # LEFT_RIGHT: z -> -z; the east-facing stairs keep their facing (not across their axis), the
    # chest faces south (HorizontalDirectionalBlock.mirror); the armor stand's yaw is 180 - yaw
    "place template demo:room ~3 ~3 ~1 none left_right",
    "assert block ~4 ~3 ~1 oak_stairs[facing=east]",
    "assert block ~5 ~4 ~1 chest[facing=south]",
    "assert entity @e[type=armor_stand,tag=from_template,x=4.5,y=5,z=1.5,distance=..0.001,nbt={Rotation:[180.0f,0.0f]}]",
])


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_turned_or_mirrored_placement(tmp_path, backend):
    root = write(tmp_path, {"demo/structure/room.nbt": structure(BLOCKS, PALETTE, [ENTITY]),
                            "demo/test/turned.mcfunction": TURNED + "\n"})
    result = results(root, backend)["demo:turned"]
    assert result.status == "passed", result.report()


def test_what_a_placement_does_not_model(tmp_path):
    frame = {"pos": ("list", ("d", [0.5, 0.5, 0.5])), "blockPos": ints(0, 0, 0),
             "nbt": ("compound", {"id": ("str", "minecraft:item_frame")})}
    root = write(tmp_path, {"demo/structure/room.nbt": structure(BLOCKS, PALETTE, [frame]),
                            "demo/test/turned.mcfunction": "place template demo:room ~3 ~ ~ clockwise_90\n",
                            "demo/test/partial.mcfunction": "place template demo:room ~3 ~ ~ none none 0.5\n"})
    found = results(root, "python")
    for test_id, why in (("demo:turned", "item frames and paintings"), ("demo:partial", "integrity below 1")):
        assert found[test_id].status == "inconclusive" and why in found[test_id].report(), found[test_id].report()


def test_a_container_placed_with_a_loot_table_draws_its_seed(tmp_path):
    # StructureTemplate.placeInWorld: a RandomizableContainer's LootTableSeed is the placement
    # random's nextLong, whatever the template saved; other block entities keep their data as is
    blocks = [{"pos": ints(0, 0, 0), "state": ("i", 2), "nbt": ("compound", {
        "LootTable": ("str", "minecraft:chests/simple_dungeon"), "LootTableSeed": ("l", 7)})}]
    test = "\n".join(["place template demo:loot ~ ~ ~",
                      "assert block ~ ~ ~ chest{LootTable:\"minecraft:chests/simple_dungeon\"}",
                      "assert not block ~ ~ ~ chest{LootTableSeed:7L}"])
    root = write(tmp_path, {"demo/structure/loot.nbt": structure(blocks, PALETTE),
                            "demo/test/loot.mcfunction": test + "\n"})
    result = results(root, "python")["demo:loot"]
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_placed_frame_hangs_on_its_new_block(tmp_path, backend):
    """BlockAttachedEntity.setPos (placeEntities' snapTo): the block it hangs on is its new
    position's, whatever block the template saved."""
    frame = {"pos": ("list", ("d", [0.5, 0.5, 0.96875])), "blockPos": ints(0, 0, 0),
             "nbt": ("compound", {"id": ("str", "minecraft:item_frame"), "Facing": ("b", 2),
                                  "TileX": ("i", 100), "TileY": ("i", 64), "TileZ": ("i", 100)})}
    root = write(tmp_path, {"demo/structure/room.nbt": structure(BLOCKS, PALETTE, [frame]),
                            "demo/test/framed.mcfunction":
                                "place template demo:room ~3 ~ ~\n"
                                "assert entity @e[type=item_frame,nbt={TileX:3,TileY:1,TileZ:0}]\n"})
    result = results(root, backend)["demo:framed"]
    assert result.status == "passed", result.report()
