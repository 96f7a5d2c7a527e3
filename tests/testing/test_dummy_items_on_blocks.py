"""PackTest's ``dummy use block`` with an item that places no block, and the bell (emulator.world.
items_on_blocks, block_use). Sources: the game's ItemStack.useOn, Item.useOn (PASS),
HangingEntityItem.useOn, ItemFrame.calculateBoundingBox/survives, HangingEntity.setDirection,
BellBlock.useWithoutItem/onHit/isProperHit (Stats.BELL_RING), ItemUsedOnLocationTrigger."""
import json

import pytest

from tests.testing.test_dummy_hands import run

FRAME_ADVANCEMENT = {"demo/advancement/framed.json": json.dumps({"criteria": {"c": {
    "trigger": "minecraft:item_used_on_block",
    "conditions": {"location": [{"condition": "minecraft:match_tool", "predicate": {"items": "minecraft:item_frame"}},
                                {"condition": "minecraft:block_state_property", "block": "minecraft:stone"}]}}}})}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_an_item_frame_hangs_on_the_clicked_face(tmp_path, backend):
    """HangingEntityItem.useOn: the frame in the block in front of the north face, Facing 2 (north),
    yaw 180, its centre 0.46875 back toward the stone; one frame spent, used:item_frame, and
    item_used_on_block with the frame as the tool."""
    result = run(tmp_path, "# @dummy\nfill ~-1 ~ ~-1 ~3 ~3 ~3 air\n" + (
        "scoreboard objectives add used minecraft.used:minecraft.item_frame\n"
        "setblock ~1 ~1 ~2 stone\n"
        "give @s item_frame 2\n"
        "dummy @s use block ~1 ~1 ~2 north\n"
        "assert entity @e[type=item_frame,nbt={Facing:2b,Rotation:[180.0f,0.0f]}]\n"
        "execute positioned ~1.5 ~1.5 ~1.96875 run assert entity @e[type=item_frame,distance=..0.0001]\n"
        "assert items entity @s weapon.mainhand item_frame[count=1]\n"
        "assert score @s used matches 1\n"
        "assert entity @s[advancements={demo:framed=true}]\n"
        # the same face again: the new frame's box meets the first one: consumed, nothing placed
        "dummy @s use block ~1 ~1 ~2 north\n"
        "execute store result score #frames used if entity @e[type=item_frame]\n"
        "assert score #frames used matches 1\n"
        "assert items entity @s weapon.mainhand item_frame[count=1]\n"
        # on top: pitch -90, Facing 1
        "dummy @s use block ~1 ~1 ~2 up\n"
        "assert entity @e[type=item_frame,nbt={Facing:1b,Rotation:[0.0f,-90.0f]}]\n"
        "assert not items entity @s weapon.mainhand *\n"), files=FRAME_ADVANCEMENT, backend=backend)
    assert result.status == "passed", result.report()


def test_an_item_frame_does_not_hang_on_air_or_into_a_block(tmp_path):
    """ItemFrame.survives: the block behind must be solid and its own block free of collision."""
    result = run(tmp_path, "# @dummy\nfill ~-1 ~ ~-1 ~3 ~3 ~3 air\n" + (
        "setblock ~1 ~1 ~2 stone\n"
        "setblock ~1 ~1 ~1 stone\n"
        "give @s item_frame\n"
        "dummy @s use block ~1 ~1 ~2 north\n"
        "assert not entity @e[type=item_frame]\n"
        "assert items entity @s weapon.mainhand item_frame\n"))
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("item", ["emerald", "bucket", "ender_eye", "minecart", "potion[potion_contents=\"water\"]"])
def test_an_item_without_a_use_on_blocks_passes(tmp_path, item):
    """Item.useOn: PASS (an emerald; a bucket, which acts through Item.use's own ray); items whose
    useOn acts on some blocks only pass or fail on stone (EnderEyeItem: an end portal frame;
    MinecartItem: a rail, FAIL; PotionItem: #convertable_to_mud): the dummy cannot interact."""
    result = run(tmp_path, f"# @dummy\nsetblock ~1 ~ ~ stone\ngive @s {item}\ndummy @s use block ~1 ~ ~\n"
                           "fail \"end\"\n")
    assert (result.status, result.message) == ("failed", "end")
    assert "cannot interact with that block" in "\n".join(result.details)


@pytest.mark.parametrize("face, y, rung", [("north", 0.25, True), ("north", 0.9, False), ("east", 0.25, False),
                                           ("up", 0.5, False)])
def test_a_floor_bell_rings_when_struck_on_a_side_across_its_facing(tmp_path, face, y, rung):
    """BellBlock.isProperHit: a side (not up/down) no higher than 0.8124 in the block; a floor bell
    facing north rings from its north and south sides; onHit awards bell_ring. A miss passes on to
    the held emerald, whose use passes: the dummy cannot interact."""
    result = run(tmp_path, "# @dummy\nfill ~-1 ~ ~-1 ~3 ~3 ~3 air\n" + (
        "scoreboard objectives add rung minecraft.custom:minecraft.bell_ring\n"
        "setblock ~1 ~1 ~1 bell\n"
        "give @s emerald\n"
        f"dummy @s use block ~1.4 ~{1 + y} ~1.5 {face}\n"
        f"assert {'' if rung else 'not '}score @s rung matches 1\n"
        "fail \"end\"\n"))
    assert (result.status, result.message) == ("failed", "end"), result.report()
    assert ("cannot interact with that block" in "\n".join(result.details)) == (not rung)


PLACED_FIRE = {"demo/advancement/fire.json": json.dumps({"criteria": {"c": {
    "trigger": "minecraft:placed_block",
    "conditions": {"location": [{"condition": "minecraft:match_tool", "predicate": {"items": "minecraft:flint_and_steel"}},
                                {"condition": "minecraft:block_state_property", "block": "minecraft:nether_portal"}]}}}})}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_flint_and_steel_fills_an_obsidian_frame_with_a_portal(tmp_path, backend):
    """FlintAndSteelItem.useOn -> BaseFireBlock.onPlace -> PortalShape.findEmptyPortalShape (x first):
    a 2 x 3 frame along x fills with nether_portal[axis=x]; placed_block at the fire's block, the
    flint and steel worn by one, used:flint_and_steel."""
    result = run(tmp_path, "# @dummy\nfill ~-1 ~ ~-1 ~4 ~5 ~3 air\n" + (
        "scoreboard objectives add used minecraft.used:minecraft.flint_and_steel\n"
        "fill ~ ~ ~2 ~3 ~4 ~2 obsidian\n"
        "fill ~1 ~1 ~2 ~2 ~3 ~2 air\n"
        "item replace entity @s weapon.mainhand with flint_and_steel\n"
        "dummy @s use block ~1 ~ ~2 up\n"
        "assert block ~1 ~1 ~2 nether_portal[axis=x]\n"
        "assert block ~2 ~3 ~2 nether_portal[axis=x]\n"
        "assert block ~ ~1 ~2 obsidian\n"
        "assert items entity @s weapon.mainhand flint_and_steel[damage=1]\n"
        "assert score @s used matches 1\n"
        "assert entity @s[advancements={demo:fire=true}]\n"), files=PLACED_FIRE, backend=backend)
    assert result.status == "passed", result.report()


def test_flint_and_steel_on_a_frame_too_small_lights_a_fire_whose_ticks_are_not_modelled(tmp_path):
    """PortalShape: a 1-wide frame is no portal; the fire stands on the obsidian's sturdy top
    (FireBlock.getStateForPlacement: age 0, no sides). FireBlock.tick comes 30 to 39 ticks later:
    reported as not modelled."""
    result = run(tmp_path, "# @dummy\nfill ~-1 ~ ~-1 ~4 ~5 ~3 air\n" + (
        "fill ~ ~ ~1 ~2 ~3 ~1 obsidian\n"
        "fill ~1 ~1 ~1 ~1 ~2 ~1 air\n"
        "item replace entity @s weapon.mainhand with flint_and_steel\n"
        "dummy @s use block ~1 ~ ~1 up\n"
        "assert block ~1 ~1 ~1 fire[age=0,up=false,north=false]\n"
        "assert block ~1 ~2 ~1 air\n"
        "await delay 40t\n"))
    assert result.status == "inconclusive", result.report()
    assert "FireBlock.tick" in result.report()


def test_a_fire_without_fire_ticks_stays_and_is_no_gap(tmp_path):
    """FireBlock.tick schedules its next tick, then does nothing more without doFireTick: the fire
    stands, as modelled, and the test is conclusive."""
    result = run(tmp_path, "# @dummy\nfill ~-1 ~ ~-1 ~4 ~5 ~3 air\ngamerule doFireTick false\n" + (
        "fill ~ ~ ~1 ~2 ~3 ~1 obsidian\n"
        "fill ~1 ~1 ~1 ~1 ~2 ~1 air\n"
        "item replace entity @s weapon.mainhand with flint_and_steel\n"
        "dummy @s use block ~1 ~ ~1 up\n"
        "await delay 80t\n"
        "assert block ~1 ~1 ~1 fire[age=0]\n"))
    assert result.status == "passed", result.report()


def test_flint_and_steel_lights_a_campfire(tmp_path):
    """CampfireBlock.canLight: unlit, not waterlogged: lit=true, the item worn."""
    result = run(tmp_path, "# @dummy\nfill ~-1 ~ ~-1 ~3 ~3 ~3 air\n" + (
        "setblock ~1 ~ ~1 campfire[lit=false]\n"
        "item replace entity @s weapon.mainhand with flint_and_steel\n"
        "dummy @s use block ~1 ~ ~1 up\n"
        "assert block ~1 ~ ~1 campfire[lit=true]\n"
        "assert items entity @s weapon.mainhand flint_and_steel[damage=1]\n"))
    assert result.status == "passed", result.report()


AXE_ADVANCEMENT = {"demo/advancement/stripped.json": json.dumps({"criteria": {"c": {
    "trigger": "minecraft:item_used_on_block",
    "conditions": {"location": [{"condition": "minecraft:block_state_property", "block": "minecraft:oak_log"}]}}}})}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_hoe_tills_a_shovel_flattens_an_axe_strips_and_scrapes(tmp_path, backend):
    """HoeItem.useOn (grass -> farmland, coarse dirt -> dirt, air above), ShovelItem.useOn (dirt ->
    dirt_path; a lit campfire put out), AxeItem.useOn (oak_log keeps its axis; copper scraped one
    stage; wax off); each wears the tool by one. The axe fires item_used_on_block before the change
    (the log as it was)."""
    result = run(tmp_path, "# @dummy\nfill ~-1 ~ ~-1 ~3 ~3 ~3 air\n" + (
        "setblock ~1 ~ ~ grass_block\nsetblock ~2 ~ ~ coarse_dirt\nsetblock ~1 ~ ~1 dirt\n"
        "setblock ~2 ~ ~1 campfire[lit=true]\nsetblock ~1 ~ ~2 oak_log[axis=x]\n"
        "setblock ~2 ~ ~2 weathered_cut_copper\nsetblock ~ ~ ~2 waxed_copper_block\n"
        "item replace entity @s weapon.mainhand with iron_hoe\n"
        "dummy @s use block ~1 ~ ~ up\n"
        "dummy @s use block ~2 ~ ~ north\n"
        "assert block ~1 ~ ~ farmland[moisture=0]\n"
        "assert block ~2 ~ ~ dirt\n"
        "assert items entity @s weapon.mainhand iron_hoe[damage=2]\n"
        "item replace entity @s weapon.mainhand with iron_shovel\n"
        "dummy @s use block ~1 ~ ~1 up\n"
        "dummy @s use block ~2 ~ ~1 up\n"
        "assert block ~1 ~ ~1 dirt_path\n"
        "assert block ~2 ~ ~1 campfire[lit=false]\n"
        "item replace entity @s weapon.mainhand with iron_axe\n"
        "dummy @s use block ~1 ~ ~2 up\n"
        "assert block ~1 ~ ~2 stripped_oak_log[axis=x]\n"
        "assert entity @s[advancements={demo:stripped=true}]\n"
        "dummy @s use block ~2 ~ ~2 up\n"
        "assert block ~2 ~ ~2 exposed_cut_copper\n"
        "dummy @s use block ~ ~ ~2 up\n"
        "assert block ~ ~ ~2 copper_block\n"
        "assert items entity @s weapon.mainhand iron_axe[damage=3]\n"), files=AXE_ADVANCEMENT, backend=backend)
    assert result.status == "passed", result.report()


def test_a_hoe_needs_air_above_and_an_axe_yields_to_a_shield(tmp_path):
    """HoeItem.onlyIfAirAbove; AxeItem.playerHasShieldUseIntent: a main-hand axe with a shield in
    the offhand passes (then the offhand's shield has no use on blocks): nothing changes."""
    result = run(tmp_path, "# @dummy\nfill ~-1 ~ ~-1 ~3 ~3 ~3 air\n" + (
        "setblock ~1 ~ ~ dirt\nsetblock ~1 ~1 ~ stone\nsetblock ~2 ~ ~ oak_log\n"
        "item replace entity @s weapon.mainhand with iron_hoe\n"
        "dummy @s use block ~1 ~ ~ north\n"
        "assert block ~1 ~ ~ dirt\n"
        "item replace entity @s weapon.mainhand with iron_axe\n"
        "item replace entity @s weapon.offhand with shield\n"
        "dummy @s use block ~2 ~ ~ up\n"
        "assert block ~2 ~ ~ oak_log\n"
        "fail \"end\"\n"))
    assert (result.status, result.message) == ("failed", "end"), result.report()
    assert "cannot interact with that block" in "\n".join(result.details)


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_buckets_and_bottles_fill_and_empty_a_cauldron(tmp_path, backend):
    """CauldronInteraction: a water bucket fills any cauldron to level 3 (fill_cauldron, an empty
    bucket back); a glass bottle takes a level (a water bottle, use_cauldron); a water bottle puts
    one back; an empty bucket takes only a full one (fillBucket), leaving a cauldron."""
    result = run(tmp_path, "# @dummy\nfill ~-1 ~ ~-1 ~3 ~3 ~3 air\n" + (
        "scoreboard objectives add filled minecraft.custom:minecraft.fill_cauldron\n"
        "scoreboard objectives add used minecraft.custom:minecraft.use_cauldron\n"
        "setblock ~1 ~ ~1 cauldron\n"
        "item replace entity @s weapon.mainhand with water_bucket\n"
        "dummy @s use block ~1 ~ ~1 up\n"
        "assert block ~1 ~ ~1 water_cauldron[level=3]\n"
        "assert items entity @s weapon.mainhand bucket\n"
        "assert score @s filled matches 1\n"
        "item replace entity @s weapon.mainhand with glass_bottle 2\n"
        "dummy @s use block ~1 ~ ~1 up\n"
        "assert block ~1 ~ ~1 water_cauldron[level=2]\n"
        "assert items entity @s weapon.mainhand glass_bottle[count=1]\n"
        "assert items entity @s container.* potion[potion_contents={potion:\"minecraft:water\"}]\n"
        "item replace entity @s weapon.mainhand with bucket\n"
        "dummy @s use block ~1 ~ ~1 up\n"
        "assert block ~1 ~ ~1 water_cauldron[level=2]\n"
        "item replace entity @s weapon.mainhand with potion[potion_contents={potion:\"minecraft:water\"}]\n"
        "dummy @s use block ~1 ~ ~1 up\n"
        "assert block ~1 ~ ~1 water_cauldron[level=3]\n"
        "assert items entity @s weapon.mainhand glass_bottle\n"
        "item replace entity @s weapon.mainhand with bucket\n"
        "dummy @s use block ~1 ~ ~1 up\n"
        "assert block ~1 ~ ~1 cauldron\n"
        "assert items entity @s weapon.mainhand water_bucket\n"
        "assert score @s used matches 3\n"), pack_format=48, backend=backend)
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_an_armor_stand_stands_on_the_clicked_block_turned_to_the_player(tmp_path, backend):
    """ArmorStandItem.useOn: at the bottom centre of the block above the clicked top, yaw =
    floor((wrapDegrees(yaw - 180) + 22.5) / 45) x 45 (the dummy at yaw 100: -80 -> -90), its
    custom_name; one spent, used:armor_stand; again in the same place an entity is in the way: FAIL."""
    result = run(tmp_path, "# @dummy\nfill ~-1 ~ ~-1 ~3 ~3 ~3 air\n" + (
        "scoreboard objectives add used minecraft.used:minecraft.armor_stand\n"
        "setblock ~1 ~ ~1 stone\n"
        "tp @s ~ ~ ~ 100 0\n"
        "item replace entity @s weapon.mainhand with armor_stand[custom_name='\"Stan\"'] 2\n"
        "dummy @s use block ~1 ~ ~1 up\n"
        "execute positioned ~1.5 ~1 ~1.5 run assert entity @e[type=armor_stand,name=Stan,distance=..0.0001,"
        "y_rotation=-90]\n"
        "assert items entity @s weapon.mainhand armor_stand[count=1]\n"
        "assert score @s used matches 1\n"
        "dummy @s use block ~1 ~ ~1 up\n"
        "assert items entity @s weapon.mainhand armor_stand[count=1]\n"
        "fail \"end\"\n"), backend=backend)
    assert (result.status, result.message) == ("failed", "end"), result.report()
    assert "cannot interact with that block" in "\n".join(result.details)


def test_a_water_bottle_turns_dirt_to_mud(tmp_path):
    """PotionItem.useOn: water on dirt (not from below) -> mud, a glass bottle back; used:potion is
    awarded by PotionItem and again by ItemStack.useOn."""
    result = run(tmp_path, "# @dummy\nfill ~-1 ~ ~-1 ~3 ~3 ~3 air\n" + (
        "scoreboard objectives add used minecraft.used:minecraft.potion\n"
        "setblock ~1 ~ ~1 dirt\n"
        "item replace entity @s weapon.mainhand with potion[potion_contents={potion:\"minecraft:water\"}]\n"
        "dummy @s use block ~1 ~ ~1 up\n"
        "assert block ~1 ~ ~1 mud\n"
        "assert items entity @s weapon.mainhand glass_bottle\n"
        "assert score @s used matches 2\n"))
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("pack_format, key", [(48, "TileX"), (71, "block_pos")])  # 1.21, 1.21.5
def test_a_frame_saves_its_block_as_its_release_does(tmp_path, pack_format, key):
    """BlockAttachedEntity.addAdditionalSaveData: TileX/TileY/TileZ before 1.21.5, block_pos from it
    (vanilla-mcdoc's BlockAttachedEntity: TileX until 1.21.5, block_pos since)."""
    result = run(tmp_path, "# @dummy\nfill ~-1 ~ ~-1 ~3 ~3 ~3 air\n" + (
        "scoreboard objectives add t dummy\n"
        "setblock ~1 ~1 ~2 stone\n"
        "give @s item_frame\n"
        "dummy @s use block ~1 ~1 ~2 north\n"
        "data modify storage t:t frame set from entity @e[type=item_frame,limit=1]\n"
        f"execute store success score #saved t run data get storage t:t frame.{key}\n"
        "assert score #saved t matches 1\n"), pack_format=pack_format)
    assert result.status == "passed", result.report()
