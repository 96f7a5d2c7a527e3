"""PackTest's ``dummy use entity`` (emulator.world.entity_use). Sources: misode/packtest
DummyCommand.useEntity (each hand through Player.interactOn until one consumes the action), the
game's Interaction.interact, ItemFrame.interact (1.21.2+ results), Entity.interact."""
import pytest

from tests.testing.test_dummy_hands import run


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_an_item_frame_takes_the_held_item_then_turns_it(tmp_path, backend):
    result = run(tmp_path, "# @dummy\n" + (
        "summon item_frame ~1 ~1 ~ {Tags:[\"f\"]}\n"
        "give @s stone 3\n"
        "dummy @s use entity @e[tag=f,limit=1]\n"
        "assert data entity @e[tag=f,limit=1] {Item:{id:\"minecraft:stone\",count:1}}\n"
        "assert items entity @s weapon.mainhand stone[count=2]\n"
        "dummy @s use entity @e[tag=f,limit=1]\n"
        "dummy @s use entity @e[tag=f,limit=1]\n"
        "assert data entity @e[tag=f,limit=1] {ItemRotation:2b}\n"
        "assert items entity @s weapon.mainhand stone[count=2]\n"), pack_format=61, backend=backend)
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("pack_format, refused", [(61, True), (48, False)])
def test_an_empty_frame_with_empty_hands_passes_from_1_21_2(tmp_path, pack_format, refused):
    result = run(tmp_path, "# @dummy\nsummon item_frame ~1 ~1 ~ {Tags:[\"f\"]}\n"
                           "dummy @s use entity @e[tag=f,limit=1]\nfail \"end\"\n", pack_format=pack_format)
    assert (result.status, result.message) == ("failed", "end")
    assert ("cannot interact with that entity" in "\n".join(result.details)) == refused


def test_using_an_entity_without_an_interaction_is_refused(tmp_path):
    result = run(tmp_path, "# @dummy\nsummon marker ~1 ~ ~\ndummy @s use entity @e[type=marker,limit=1]\n"
                           "fail \"end\"\n")
    assert "cannot interact with that entity" in "\n".join(result.details)


# ---------------------------------------------------------------------- armor stands
@pytest.mark.parametrize("backend", ["numba", "python"])
def test_an_armor_stand_with_arms_takes_the_held_item_in_its_hand(tmp_path, backend):
    """ArmorStand.interactAt -> swapItem: paper goes to the main hand (getEquipmentSlotForItem), the
    player's hand of one item trades whole; a carved pumpkin goes to the head from a stack one at a time."""
    result = run(tmp_path, "# @dummy\n" + (
        "summon armor_stand ~1 ~ ~ {ShowArms:1b,Tags:[\"s\"]}\n"
        "item replace entity @s weapon.mainhand with paper\n"
        "dummy @s use entity @e[tag=s,limit=1]\n"
        "assert items entity @e[tag=s] weapon.mainhand paper\n"
        "assert not items entity @s weapon.mainhand *\n"
        "item replace entity @s weapon.mainhand with carved_pumpkin 2\n"
        "dummy @s use entity @e[tag=s,limit=1]\n"
        "assert items entity @e[tag=s] armor.head carved_pumpkin[count=1]\n"
        "assert items entity @s weapon.mainhand carved_pumpkin[count=1]\n"), backend=backend)
    assert result.status == "passed", result.report()


def test_an_armor_stand_without_arms_refuses_a_hand_item(tmp_path):
    """ArmorStand.interactAt: a hand slot on a stand without arms is disabled: FAIL, nothing moves."""
    result = run(tmp_path, "# @dummy\n" + (
        "summon armor_stand ~1 ~ ~ {Tags:[\"s\"]}\n"
        "give @s paper\n"
        "dummy @s use entity @e[tag=s,limit=1]\n"
        "assert items entity @s weapon.mainhand paper\n"
        "fail \"end\"\n"))
    assert (result.status, result.message) == ("failed", "end")
    assert "cannot interact with that entity" in "\n".join(result.details)


def test_an_empty_hand_takes_the_slot_clicked_at_the_height_given(tmp_path):
    """ArmorStand.getClickedSlot: the click's y over the scale (PackTest passes the position as
    written, a world position) picks the head at 1.6 and above, the main hand below the armour's
    bands; an empty slot passes."""
    result = run(tmp_path, "# @dummy\n" + (
        "summon armor_stand ~1 ~ ~ {Tags:[\"s\"],ArmorItems:[{},{},{},{id:\"minecraft:stone\",count:1}]}\n"
        "dummy @s use entity @e[tag=s,limit=1] 0 0.05 0\n"
        "assert not items entity @s weapon.mainhand *\n"
        "dummy @s use entity @e[tag=s,limit=1] 0 1.7 0\n"
        "assert items entity @s weapon.mainhand stone\n"
        "assert not items entity @e[tag=s] armor.head *\n"))
    assert result.status == "passed", result.report()
    assert "cannot interact with that entity" in "\n".join(result.details)


def test_a_name_tag_names_an_armor_stand(tmp_path):
    """ArmorStand.interactAt passes a name tag; NameTagItem.interactLivingEntity names it and is spent."""
    result = run(tmp_path, "# @dummy\n" + (
        "summon armor_stand ~1 ~ ~ {Tags:[\"s\"]}\n"
        "item replace entity @s weapon.mainhand with name_tag[custom_name='\"Bob\"'] 2\n"
        "dummy @s use entity @e[tag=s,limit=1]\n"
        "assert entity @e[tag=s,name=Bob]\n"
        "assert items entity @s weapon.mainhand name_tag[count=1]\n"))
    assert result.status == "passed", result.report()


# ---------------------------------------------------------------------- mobs
PIG_FOOD = {"minecraft/tags/item/pig_food.json": '{"replace": true, "values": ["carrot", "potato", "beetroot"]}',
            "minecraft/tags/item/cow_food.json": '{"replace": true, "values": ["wheat"]}'}


def _files(extra=None):
    return {**PIG_FOOD, **(extra or {})}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_saddle_saddles_a_pig_and_the_next_use_rides_it(tmp_path, backend):
    """Pig.mobInteract: no saddle -> SaddleItem.interactLivingEntity (Saddle:1b, one spent); saddled,
    no rider, not food -> Player.startRiding: the vehicle relation, the rider on the attachment
    (0.86875 - 0.6 above the pig), started_riding."""
    adv = ('{"criteria": {"r": {"trigger": "minecraft:started_riding"}}, '
           '"rewards": {"function": "demo:rode"}}')
    result = run(tmp_path, "# @dummy\n" + (
        "summon pig ~1 ~ ~ {Tags:[\"p\"],NoAI:1b}\n"
        "give @s saddle\n"
        "dummy @s use entity @e[tag=p,limit=1]\n"
        "assert entity @e[tag=p,nbt={Saddle:1b}]\n"
        "assert not items entity @s weapon.mainhand *\n"
        "dummy @s use entity @e[tag=p,limit=1]\n"
        "execute on vehicle run assert entity @s[tag=p]\n"
        "assert entity @s[tag=rode]\n"
        "execute at @e[tag=p] positioned ~ ~0.26875 ~ run assert entity @p[distance=..0.0001]\n"
        # Entity.rideTick: the rider neither falls nor moves while the pig stands
        "await delay 5t\n"
        "execute at @e[tag=p] positioned ~ ~0.26875 ~ run assert entity @p[distance=..0.0001]\n"),
        files=_files({"demo/advancement/ride.json": adv, "demo/function/rode.mcfunction": "tag @s add rode\n"}),
        backend=backend)
    assert result.status == "passed", result.report()


def test_a_sneaking_rider_getting_off_is_not_modelled(tmp_path):
    """Player.rideTick: wantsToStopRiding (sneaking) dismounts; where it is put down is not modelled."""
    result = run(tmp_path, "# @dummy\n" + (
        "summon pig ~1 ~ ~ {Tags:[\"p\"],NoAI:1b,Saddle:1b}\n"
        "dummy @s use entity @e[tag=p,limit=1]\n"
        "dummy @s sneak true\n"
        "await delay 1t\n"), files=_files())
    assert result.status == "inconclusive", result.report()
    assert "getting off minecraft:pig" in result.report()


def test_food_for_a_pig_skips_the_ride_and_breeding_is_not_modelled(tmp_path):
    """Pig.mobInteract: food skips the ride; Animal.mobInteract would put it in love (InLove 600,
    counting down over the ticks, the breed goal): not modelled."""
    result = run(tmp_path, "# @dummy\n" + (
        "summon pig ~1 ~ ~ {Tags:[\"p\"],NoAI:1b,Saddle:1b}\n"
        "give @s carrot 3\n"
        "dummy @s use entity @e[tag=p,limit=1]\n"), files=_files())
    assert result.status == "inconclusive", result.report()
    assert "breeding minecraft:pig" in result.report()


def test_a_bucket_milks_a_cow(tmp_path):
    """Cow.mobInteract -> ItemUtils.createFilledResult: one bucket of two spent, the milk added."""
    result = run(tmp_path, "# @dummy\n" + (
        "summon cow ~1 ~ ~ {Tags:[\"c\"],NoAI:1b}\n"
        "give @s bucket 2\n"
        "dummy @s use entity @e[tag=c,limit=1]\n"
        "assert items entity @s weapon.mainhand bucket[count=1]\n"
        "assert items entity @s container.* milk_bucket\n"
        "dummy @s use entity @e[tag=c,limit=1]\n"
        "assert items entity @s weapon.mainhand milk_bucket\n"), files=_files())
    assert result.status == "passed", result.report()


def test_a_name_tag_names_a_mob_and_keeps_it(tmp_path):
    """Mob.checkAndHandleImportantInteractions -> NameTagItem: the name, PersistenceRequired."""
    result = run(tmp_path, "# @dummy\n" + (
        "summon zombie ~1 ~ ~ {Tags:[\"z\"],NoAI:1b}\n"
        "item replace entity @s weapon.mainhand with name_tag[custom_name='\"Zed\"']\n"
        "dummy @s use entity @e[tag=z,limit=1]\n"
        "assert entity @e[tag=z,name=Zed,nbt={PersistenceRequired:1b}]\n"
        "assert not items entity @s weapon.mainhand *\n"))
    assert result.status == "passed", result.report()


def test_talking_to_a_villager_without_trades_counts(tmp_path):
    """Villager.mobInteract: no offers (no profession): talked_to_villager for the main hand, CONSUME."""
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add talked minecraft.custom:minecraft.talked_to_villager\n"
        "summon villager ~1 ~ ~ {NoAI:1b,VillagerData:{profession:\"minecraft:none\",level:1,type:\"minecraft:plains\"}}\n"
        "dummy @s use entity @e[type=villager,limit=1]\n"
        "assert score @s talked matches 1\n"))
    assert result.status == "passed", result.report()


def test_a_trading_villager_stays_unmodelled(tmp_path):
    result = run(tmp_path, "# @dummy\nsummon villager ~1 ~ ~ {NoAI:1b,VillagerData:{profession:\"minecraft:farmer\","
                           "level:1,type:\"minecraft:plains\"}}\ndummy @s use entity @e[type=villager,limit=1]\n")
    assert result.status == "inconclusive"
    assert "first trades of minecraft:villager" in result.report()


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_shears_shear_a_sheep_once(tmp_path, backend):
    """Sheep.mobInteract -> shear (1.21.1): Sheared:1b, 1 to 3 wool of its Color one block above
    it, the shears worn by one; a sheared sheep still consumes the use (nothing more dropped)."""
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add t dummy\n"
        "summon sheep ~1 ~ ~ {Tags:[\"s\"],NoAI:1b,Color:14b}\n"
        "item replace entity @s weapon.mainhand with shears\n"
        "dummy @s use entity @e[tag=s,limit=1]\n"
        "assert entity @e[tag=s,nbt={Sheared:1b}]\n"
        "execute store result score #wool t if entity @e[type=item,nbt={Item:{id:\"minecraft:red_wool\"}}]\n"
        "assert score #wool t matches 1..3\n"
        "assert items entity @s weapon.mainhand shears[damage=1]\n"
        "dummy @s use entity @e[tag=s,limit=1]\n"
        "execute store result score #again t if entity @e[type=item]\n"
        "assert score #again t = #wool t\n"
        "assert items entity @s weapon.mainhand shears[damage=1]\n"), backend=backend)
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("vehicle, rise", [("oak_boat", "-0.4125"), ("minecart", "-0.4125")])
def test_a_boat_or_minecart_takes_the_dummy_aboard(tmp_path, vehicle, rise):
    """Boat.interact / Minecart.interact -> Player.startRiding: the dummy rides it, a boat's
    attachment a third of its 0.5625 height, a minecart's 0.1875, less the player's 0.6; a second
    use passes (the seat is taken by itself: startRiding refuses the vehicle it rides), a sneaking
    dummy passes."""
    result = run(tmp_path, "# @dummy\n" + (
        f"summon {vehicle} ~1 ~ ~ {{Tags:[\"v\"]}}\n"
        "dummy @s use entity @e[tag=v,limit=1]\n"
        "execute on vehicle run assert entity @s[tag=v]\n"
        f"execute at @e[tag=v] positioned ~ ~{rise} ~ run assert entity @p[distance=..0.0001]\n"
        "dummy @s use entity @e[tag=v,limit=1]\n"
        "fail \"end\"\n"), pack_format=61)
    assert (result.status, result.message) == ("failed", "end"), result.report()
    assert "cannot interact with that entity" in "\n".join(result.details)


def test_a_boat_turns_its_rider_within_105_degrees_of_its_bow(tmp_path):
    """Boat.positionRider -> clampRotation: the dummy looking 180 degrees from the boat's yaw turns
    to 105 degrees from it."""
    result = run(tmp_path, "# @dummy\n" + (
        "summon oak_boat ~1 ~ ~ {Tags:[\"v\"],Rotation:[0.0f,0.0f]}\n"
        "tp @s ~ ~ ~ 180 0\n"
        "dummy @s use entity @e[tag=v,limit=1]\n"
        "assert entity @s[y_rotation=-105]\n"), pack_format=61)
    assert result.status == "passed", result.report()


OFFERS = ('Offers:{Recipes:[{buy:{id:"minecraft:emerald",count:1},sell:{id:"minecraft:bread",count:1},'
          'maxUses:12}]}')


def test_a_merchant_with_offers_opens_its_trades_and_closes_an_open_container(tmp_path):
    """Villager.mobInteract -> startTrading: talked_to_villager; Player.openMenu closes the barrel
    the dummy had open (BarrelBlockEntity.stopOpen: open=false)."""
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add talked minecraft.custom:minecraft.talked_to_villager\n"
        "setblock ~2 ~ ~ barrel\n"
        "dummy @s use block ~2 ~ ~\n"
        "assert block ~2 ~ ~ barrel[open=true]\n"
        f"summon villager ~1 ~ ~1 {{NoAI:1b,VillagerData:{{profession:\"minecraft:farmer\",level:1,"
        f"type:\"minecraft:plains\"}},{OFFERS}}}\n"
        "dummy @s use entity @e[type=villager,limit=1]\n"
        "assert score @s talked matches 1\n"
        "assert block ~2 ~ ~ barrel[open=false]\n"))
    assert result.status == "passed", result.report()


def test_using_a_merchant_again_while_it_may_trade_is_not_modelled(tmp_path):
    result = run(tmp_path, "# @dummy\n" + (
        f"summon wandering_trader ~1 ~ ~1 {{NoAI:1b,{OFFERS}}}\n"
        "dummy @s use entity @e[type=wandering_trader,limit=1]\n"
        "dummy @s use entity @e[type=wandering_trader,limit=1]\n"))
    assert result.status == "inconclusive", result.report()
    assert "after its trading menu opened" in result.report()


def test_using_another_player_passes(tmp_path):
    """Entity.interact (a player is not Leashable) passes, and a name tag does not name a player
    (NameTagItem): the dummy cannot interact."""
    result = run(tmp_path, "# @dummy\n" + (
        "dummy Alex spawn\n"
        "item replace entity @s weapon.mainhand with name_tag[custom_name='\"Bob\"']\n"
        "dummy @s use entity Alex\n"
        "assert items entity @s weapon.mainhand name_tag\n"
        "fail \"end\"\n"))
    assert (result.status, result.message) == ("failed", "end"), result.report()
    assert "cannot interact with that entity" in "\n".join(result.details)
