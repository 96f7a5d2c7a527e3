"""``place template``: a pack's structure file placed by a command, as libraries place their
prefabs (PlaceCommand.placeTemplate, decompiled 1.21: the template from the structure manager, its
corner at the position or the source's block, StructureTemplate.placeInWorld with no rotation or
mirror; "There is no template with id" and "Failed to place template" fail the command)."""
import pytest

from tests.testing.test_structures import BLOCKS, ENTITY, PALETTE, ints, nbt_file, results, structure, write

TEST = "\n".join([
    "scoreboard objectives add t dummy",
    "place template demo:room ~3 ~ ~",
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


def test_a_rotated_or_partial_placement_is_not_modelled(tmp_path):
    root = write(tmp_path, {"demo/structure/room.nbt": structure(BLOCKS, PALETTE),
                            "demo/test/turned.mcfunction": "place template demo:room ~3 ~ ~ clockwise_90\n",
                            "demo/test/partial.mcfunction": "place template demo:room ~3 ~ ~ none none 0.5\n"})
    found = results(root, "python")
    for test_id, why in (("demo:turned", "rotation clockwise_90"), ("demo:partial", "integrity below 1")):
        assert found[test_id].status == "inconclusive" and why in found[test_id].report(), found[test_id].report()
