"""Dummies placing blocks that join, come in two parts or hang on a neighbour
(emulator.world.placed_parts), with PackTest's ``use block POS [DIR]`` (the click at POS as written).
The dummy spawns at the test origin looking south (yaw 0, pitch 0): Direction.orderedByNearest
gives south, down, west, east, up, north. Sources: SlabBlock (canBeReplaced,
getStateForPlacement), DoorBlock (getStateForPlacement, getHinge, setPlacedBy), ChestBlock
(getStateForPlacement, candidatePartnerFacing, updateShape), StandingAndWallBlockItem, WallTorchBlock,
StandingSignBlock, WallSignBlock, BlockPlaceContext.getNearestLookingDirections."""
import pytest

from tests.testing.test_dummy_hands import run


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_slabs_take_their_half_and_join_into_a_double_slab(tmp_path, backend):
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add used minecraft.used:minecraft.oak_slab\n"
        "setblock ~2 ~ ~ stone\nsetblock ~4 ~ ~ stone\n"
        "give @s oak_slab 5\n"
        "dummy @s use block ~2 ~ ~ up\n"                  # on top of the stone: the bottom half
        "assert block ~2 ~1 ~ oak_slab[type=bottom,waterlogged=false]\n"
        "dummy @s use block ~2 ~1.5 ~ up\n"               # its open top clicked: the same slab doubles
        "assert block ~2 ~1 ~ oak_slab[type=double]\n"
        "dummy @s use block ~4 ~0.75 ~0.5 west\n"         # a side clicked above the middle: the top half
        "assert block ~3 ~ ~ oak_slab[type=top]\n"
        "dummy @s use block ~3 ~ ~0.5 down\n"             # the top slab's open underside
        "assert block ~3 ~ ~ oak_slab[type=double]\n"
        "dummy @s use block ~2 ~1.5 ~ up\n"               # a double slab takes no more: above it
        "assert block ~2 ~2 ~ oak_slab[type=bottom]\n"
        "assert score @s used matches 5\n"), backend=backend)
    assert result.status == "passed", result.report()


def test_a_door_places_both_halves_with_its_hinge_from_the_neighbours_and_the_click(tmp_path):
    """Facing the player's direction (south); nothing beside: the click decides (on the corner of a
    south-facing door's block: right; past its middle in x: left); full blocks on its left (east,
    counter-clockwise of south) turn the hinge left; a redstone block beside powers and opens it."""
    result = run(tmp_path, "# @dummy\n" + (
        "fill ~2 ~ ~ ~12 ~ ~ stone\n"
        "setblock ~5 ~1 ~ stone\nsetblock ~5 ~2 ~ stone\nsetblock ~9 ~1 ~1 redstone_block\n"
        "give @s oak_door 4\n"
        "dummy @s use block ~2 ~ ~ up\n"
        "assert block ~2 ~1 ~ oak_door[facing=south,half=lower,hinge=right,open=false,powered=false]\n"
        "assert block ~2 ~2 ~ oak_door[facing=south,half=upper,hinge=right,open=false,powered=false]\n"
        "dummy @s use block ~4.25 ~ ~ up\n"
        "assert block ~4 ~1 ~ oak_door[hinge=left,half=lower]\n"
        "dummy @s use block ~11.75 ~ ~ up\n"
        "assert block ~11 ~1 ~ oak_door[hinge=left]\n"
        "dummy @s use block ~9 ~ ~ up\n"
        "assert block ~9 ~1 ~ oak_door[open=true,powered=true]\n"
        "assert block ~9 ~2 ~ oak_door[half=upper,open=true]\n"))
    assert result.status == "passed", result.report()


def test_a_door_needs_room_above_and_a_floor(tmp_path):
    result = run(tmp_path, "# @dummy\n" + (
        "setblock ~2 ~ ~ stone\nsetblock ~2 ~2 ~ stone\n"
        "give @s oak_door 2\n"
        "dummy @s use block ~2 ~1 ~ up\n"                 # the upper half has no room
        "assert block ~2 ~1 ~ air\n"
        "dummy @s use block ~4 ~1 ~ up\n"                 # nothing to stand on (air is clicked, replaced)
        "assert block ~4 ~1 ~ air\n"
        "assert items entity @s weapon.mainhand oak_door[count=2]\n"))
    assert result.status == "passed", result.report()


def test_a_chest_beside_a_chest_facing_the_same_way_makes_a_double_chest(tmp_path):
    """Both face the player (north); the second finds a single chest counter-clockwise of its
    facing (west): it is the right half and the first becomes the left; sneaking, a chest placed
    on top of a block stays single; a trapped chest does not join a chest."""
    result = run(tmp_path, "# @dummy\n" + (
        "fill ~2 ~ ~ ~6 ~ ~ stone\n"
        "give @s chest 3\n"
        "dummy @s use block ~2 ~1 ~ up\n"
        "assert block ~2 ~1 ~ chest[facing=north,type=single,waterlogged=false]\n"
        "dummy @s use block ~3 ~1 ~ up\n"
        "assert block ~3 ~1 ~ chest[facing=north,type=right]\n"
        "assert block ~2 ~1 ~ chest[facing=north,type=left]\n"
        "dummy @s sneak true\n"
        "dummy @s use block ~5 ~1 ~ up\n"
        "item replace entity @s weapon.mainhand with trapped_chest\n"
        "dummy @s sneak false\n"
        "dummy @s use block ~6 ~1 ~ up\n"
        "assert block ~5 ~1 ~ chest[type=single]\n"
        "assert block ~6 ~1 ~ trapped_chest[type=single]\n"))
    assert result.status == "passed", result.report()


def test_torches_and_signs_stand_on_a_floor_or_hang_on_the_clicked_wall(tmp_path):
    """A top face clicked: standing (down comes first); a side: on the wall, facing away from it.
    A standing sign turns opposite the player in 16 steps (yaw 0: 8, yaw 90: 12)."""
    result = run(tmp_path, "# @dummy\n" + (
        "setblock ~3 ~ ~ stone\nsetblock ~5 ~ ~ stone\nsetblock ~7 ~ ~ stone\nsetblock ~9 ~ ~ stone\n"
        "give @s torch 2\n"
        "dummy @s use block ~3 ~ ~ up\n"
        "assert block ~3 ~1 ~ torch\n"
        "dummy @s use block ~5 ~0.5 ~0.5 west\n"
        "assert block ~4 ~ ~ wall_torch[facing=west]\n"
        "item replace entity @s weapon.mainhand with oak_sign 2\n"
        "dummy @s use block ~7 ~ ~ up\n"
        "assert block ~7 ~1 ~ oak_sign[rotation=8,waterlogged=false]\n"
        "assert data block ~7 ~1 ~ {front_text:{messages:['\"\"','\"\"','\"\"','\"\"'],color:\"black\"},is_waxed:0b}\n"
        "dummy @s use block ~9 ~0.5 ~0.5 west\n"
        "assert block ~8 ~ ~ oak_wall_sign[facing=west]\n"
        "tp @s ~ ~ ~ 90 0\n"
        "item replace entity @s weapon.mainhand with redstone_torch\n"
        "dummy @s use block ~9 ~ ~0.5 north\n"           # its north face
        "assert block ~9 ~ ~-1 redstone_wall_torch[facing=north,lit=true]\n"
        "item replace entity @s weapon.mainhand with oak_sign\n"
        "dummy @s use block ~5 ~1 ~ up\n"                # on top of the wall torch's block, looking west
        "assert block ~5 ~1 ~ oak_sign[rotation=12]\n"))
    assert result.status == "passed", result.report()


def test_an_unknown_shape_below_makes_the_placement_inconclusive(tmp_path):
    result = run(tmp_path, "# @dummy\n" + (
        "setblock ~3 ~ ~ oak_slab[type=bottom]\n"
        "give @s torch\n"
        "dummy @s use block ~3 ~ ~ up\n"
        "succeed\n"))
    assert result.status == "inconclusive", result.report()
    assert "the shape of minecraft:oak_slab" in result.message


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_banners_and_heads_stand_or_hang_with_an_empty_block_entity(tmp_path, backend):
    """BannerBlock: rotation opposite the player (yaw 0: 8), WallBannerBlock on the solid block
    clicked; SkullBlock: rotation with the player (yaw 0: 0), WallSkullBlock before the first block
    that is not replaceable; their block entities save nothing new (BannerBlockEntity,
    SkullBlockEntity.saveAdditional)."""
    result = run(tmp_path, "# @dummy\n" + (
        "setblock ~3 ~ ~ stone\nsetblock ~5 ~ ~ stone\nsetblock ~7 ~ ~ stone\nsetblock ~9 ~ ~ stone\n"
        "give @s white_banner 2\n"
        "dummy @s use block ~3 ~ ~ up\n"
        "assert block ~3 ~1 ~ white_banner[rotation=8]\n"
        "assert data block ~3 ~1 ~ {}\n"
        "dummy @s use block ~5 ~0.5 ~0.5 west\n"
        "assert block ~4 ~ ~ white_wall_banner[facing=west]\n"
        "item replace entity @s weapon.mainhand with skeleton_skull 2\n"
        "dummy @s use block ~7 ~ ~ up\n"
        "assert block ~7 ~1 ~ skeleton_skull[rotation=0,powered=false]\n"
        "dummy @s use block ~9 ~0.5 ~0.5 west\n"
        "assert block ~8 ~ ~ skeleton_wall_skull[facing=west,powered=false]\n"
        "assert data block ~8 ~ ~ {}\n"
        "setblock ~2 ~ ~2 zombie_head\n"
        "assert data block ~2 ~ ~2 {}\n"), backend=backend)
    assert result.status == "passed", result.report()



@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_head_keeps_the_items_profile_name_and_other_components(tmp_path, backend):
    """BlockItem.place -> BlockEntity.applyComponentsFromItemStack: SkullBlockEntity.applyImplicitComponents
    reads profile, note_block_sound and custom_name (saveAdditional: under those names; custom_name a
    JSON string before 1.21.5, a component from 1.21.5), the patch's other added components stay in
    the block entity's ``components`` (a machine library's player head placed and read back by the
    placed_block reward); a profile the game would look up (a name alone) is not modelled."""
    head = ('player_head[profile={id:[I;1,2,3,4],properties:[{name:"textures",value:"e30="}]},'
            'custom_name={"text":"Tank","italic":false},custom_data={lib:{id:"tank"}},'
            'custom_model_data={floats:[7f]}]')
    result = run(tmp_path, "# @dummy\n" + (
        "setblock ~2 ~ ~ stone\n"
        f"item replace entity @s weapon.mainhand with {head}\n"
        "dummy @s use block ~2 ~ ~ up\n"
        "assert block ~2 ~1 ~ player_head[rotation=0]\n"
        "assert data block ~2 ~1 ~ {profile:{id:[I;1,2,3,4],properties:[{name:\"textures\",value:\"e30=\"}]}}\n"
        "assert data block ~2 ~1 ~ {custom_name:{text:\"Tank\"}}\n"
        "assert data block ~2 ~1 ~ {components:{\"minecraft:custom_data\":{lib:{id:\"tank\"}},"
        "\"minecraft:custom_model_data\":{floats:[7f]}}}\n"
        "assert not data block ~2 ~1 ~ components.\"minecraft:profile\"\n"), pack_format=71, backend=backend)
    assert result.status == "passed", result.report()
    named = run(tmp_path / "named", "# @dummy\n" + (
        "setblock ~2 ~ ~ stone\n"
        'item replace entity @s weapon.mainhand with player_head[profile="Alex"]\n'
        "dummy @s use block ~2 ~ ~ up\n"), pack_format=71, backend=backend)
    assert named.status == "inconclusive" and "looks up" in named.message, named.report()

def test_hanging_signs_hang_under_a_block_or_beside_one(tmp_path):
    """CeilingHangingSignBlock: under a full face, upright, square to the player (south: rotation
    8); WallHangingSignBlock: the nearest direction off the clicked face's axis (south), facing
    away from it (north), held by the block clicked beside it. Both get a sign's block entity."""
    result = run(tmp_path, "# @dummy\n" + (
        "setblock ~3 ~2 ~ stone\nsetblock ~6 ~ ~ stone\n"
        "give @s oak_hanging_sign 2\n"
        "dummy @s use block ~3 ~2 ~ down\n"
        "assert block ~3 ~1 ~ oak_hanging_sign[attached=false,rotation=8,waterlogged=false]\n"
        "assert data block ~3 ~1 ~ {is_waxed:0b,back_text:{color:\"black\"}}\n"
        "dummy @s use block ~6 ~0.5 ~0.5 west\n"
        "assert block ~5 ~ ~ oak_wall_hanging_sign[facing=north]\n"))
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_rail_lies_along_the_player_then_joins_the_rails_round_it(tmp_path, backend):
    """BaseRailBlock.getStateForPlacement: north_south for a player facing south; onPlace ->
    RailState.place: a rail beside turns both east_west; one south of the first makes it a
    south_east curve (a plain rail's corner, the first's other end already taken); a rail a block
    up at the end of the line makes the lower one ascending_east."""
    result = run(tmp_path, "# @dummy\n" + (
        "setblock ~3 ~ ~ stone\nsetblock ~4 ~ ~ stone\nsetblock ~3 ~ ~1 stone\nsetblock ~5 ~1 ~ stone\n"
        "give @s rail 4\n"
        "dummy @s use block ~3 ~ ~ up\n"
        "assert block ~3 ~1 ~ rail[shape=north_south,waterlogged=false]\n"
        "dummy @s use block ~4 ~ ~ up\n"
        "assert block ~3 ~1 ~ rail[shape=east_west]\nassert block ~4 ~1 ~ rail[shape=east_west]\n"
        "dummy @s use block ~3 ~ ~1 up\n"
        "assert block ~3 ~1 ~1 rail[shape=north_south]\nassert block ~3 ~1 ~ rail[shape=south_east]\n"
        "dummy @s use block ~5 ~1 ~ up\n"
        "assert block ~5 ~2 ~ rail[shape=east_west]\nassert block ~4 ~1 ~ rail[shape=ascending_east]\n"), backend=backend)
    assert result.status == "passed", result.report()
