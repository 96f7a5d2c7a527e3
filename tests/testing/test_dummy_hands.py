"""PackTest dummies acting with their hands (emulator.world.player_actions): ``drop [all]``, ``swap``
and ``use item``, with what a pack observes of each. Sources: misode/packtest DummyCommand.java
(dropMainhand, swap, useItem: the main hand then the offhand until one consumes the action), the
game's ServerPlayer.drop, LivingEntity.createItemStackToDrop, FoodOnAStickItem.use,
KnowledgeBookItem.use, Consumable.startConsuming/onConsume, ServerPlayer.updateUsingItem."""
import json

import pytest

from emulator.testing import discover, run_suite
from tests.conftest import write_pack


def run(tmp_path, text, pack_format=48, files=None, backend="numba"):
    root = write_pack(tmp_path / "pack", {"demo/test/t.mcfunction": text, **(files or {})})
    meta = json.loads((root / "pack.mcmeta").read_text())
    meta["pack"]["pack_format"] = pack_format
    (root / "pack.mcmeta").write_text(json.dumps(meta))
    [result] = run_suite(discover([root]), backend).results
    return result


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_drop_throws_one_item_or_the_stack_from_the_selected_slot(tmp_path, backend):
    """ServerPlayer.drop(boolean) -> Inventory.removeFromSelected; createItemStackToDrop: eyes - 0.3,
    pickup delay 40, the thrower; ServerPlayer.drop(ItemStack, boolean, boolean) awards
    dropped:<item> with the count and custom:drop once."""
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add drops minecraft.custom:minecraft.drop\n"
        "scoreboard objectives add stones minecraft.dropped:minecraft.stone\n"
        "scoreboard objectives add t dummy\n"
        "give @s stone 5\n"
        "dummy @s drop\n"
        "assert entity @e[type=item,nbt={Item:{id:\"minecraft:stone\",count:1},PickupDelay:40s}]\n"
        "assert items entity @s weapon.mainhand stone[count=4]\n"
        "execute store result score #thrower t run data get entity @e[type=item,limit=1] Thrower[2]\n"
        "execute store result score #uuid t run data get entity @s UUID[2]\n"
        "assert score #thrower t = #uuid t\n"
        # eye height 1.62 - 0.3 above the dummy's feet
        "assert entity @e[type=item,x=0.5,y=2.32,z=0.5,distance=..0.001]\n"
        "dummy @s drop all\n"
        "assert entity @e[type=item,nbt={Item:{count:4}}]\n"
        "assert not items entity @s weapon.mainhand *\n"
        "assert score @s drops matches 2\n"
        "assert score @s stones matches 5\n"), backend=backend)
    assert result.status == "passed", result.report()


def test_dropping_with_an_empty_hand_is_refused(tmp_path):
    """DummyCommand.dropMainhand: ERROR_NOT_HOLDING_ITEM; the test goes on."""
    result = run(tmp_path, "# @dummy\ngive @s stone\ndummy @s selectslot 2\ndummy @s drop\n"
                           "assert not entity @e[type=item]\nfail \"end\"\n")
    assert (result.status, result.message) == ("failed", "end")
    assert "is not holding an item in their mainhand" in "\n".join(result.details)


@pytest.mark.parametrize("pack_format, offhand", [(48, "{Inventory:[{Slot:-106b,id:\"minecraft:stone\"}]}"),
                                                   (71, "{equipment:{offhand:{id:\"minecraft:stone\"}}}")])
def test_swap_trades_the_main_hand_and_offhand(tmp_path, pack_format, offhand):
    """DummyCommand.swap: setItemInHand both ways (the offhand saved in Inventory before 1.21.5,
    in equipment from 1.21.5)."""
    result = run(tmp_path, "# @dummy\n" + (
        "give @s stone 3\n"
        "item replace entity @s weapon.offhand with dirt 2\n"
        "dummy @s swap\n"
        "assert items entity @s weapon.offhand stone[count=3]\n"
        "assert items entity @s weapon.mainhand dirt[count=2]\n"
        f"assert data entity @s {offhand}\n"
        "dummy @s swap\n"
        "assert items entity @s weapon.mainhand stone\n"
        "assert items entity @s weapon.offhand dirt\n"), pack_format=pack_format)
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_carrot_on_a_stick_counts_used_and_the_command_fails(tmp_path, backend):
    """FoodOnAStickItem.use: not riding, it awards used:<item> and returns PASS, so the use goes on
    to the (empty) offhand and PackTest's command fails: the right-click idiom packs rely on."""
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add click minecraft.used:minecraft.carrot_on_a_stick\n"
        "scoreboard objectives add fungus used:warped_fungus_on_a_stick\n"
        "give @s carrot_on_a_stick\n"
        "item replace entity @s weapon.offhand with warped_fungus_on_a_stick\n"
        "dummy @s use item\n"
        "assert score @s click matches 1\n"
        "assert score @s fungus matches 1\n"
        "assert items entity @s weapon.mainhand carrot_on_a_stick\n"
        "fail \"end\"\n"), backend=backend)
    assert (result.status, result.message) == ("failed", "end")
    assert "cannot use that item" in "\n".join(result.details)


def test_an_empty_knowledge_book_is_consumed_and_fails(tmp_path):
    """KnowledgeBookItem.use: itemStack.consume(1, player) first; no recipes: FAIL."""
    result = run(tmp_path, "# @dummy\ngive @s knowledge_book 2\ndummy @s use item\n"
                           "assert not items entity @s hotbar.0 *\nassert items entity @s hotbar.1 knowledge_book\n",
                 pack_format=61)
    assert result.status == "passed", result.report()
    assert "cannot use that item" in "\n".join(result.details)


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_knowledge_book_teaches_its_recipes(tmp_path, backend):
    """KnowledgeBookItem.use: consumed, then every listed recipe must exist (else FAIL, logged
    "Invalid recipe"); the player learns them (ServerPlayer.awardRecipes) and used:knowledge_book
    counts; the use consumes the action."""
    recipe = json.dumps({"type": "minecraft:crafting_shapeless", "ingredients": ["minecraft:stick"],
                         "result": {"id": "minecraft:stick"}})
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add used minecraft.used:minecraft.knowledge_book\n"
        "give @s knowledge_book[recipes=['demo:wand']]\n"
        "give @s knowledge_book[recipes=['demo:wand','demo:gone']]\n"
        "dummy @s use item\n"
        "assert entity @s[nbt={recipeBook:{recipes:['demo:wand']}},scores={used=1}]\n"
        "assert not items entity @s hotbar.0 *\n"
        "recipe take @s demo:wand\n"
        "dummy @s selectslot 2\n"
        "execute store success score #ok used run dummy @s use item\n"
        "assert not entity @s[nbt={recipeBook:{recipes:['demo:wand']}}]\n"
        "assert not items entity @s hotbar.1 *\n"), files={"demo/recipe/wand.json": recipe}, pack_format=61,
        backend=backend)
    assert result.status == "passed", result.report()


USING = {
    "demo/advancement/using.json": json.dumps({
        "criteria": {"c": {"trigger": "minecraft:using_item",
                           "conditions": {"item": {"items": "minecraft:stick", "predicates": {
                               "minecraft:custom_data": "{clicker:1b}"}}}}},
        "rewards": {"function": "demo:using"}}),
    "demo/function/using.mcfunction": "scoreboard players add @s uses 1\nadvancement revoke @s only demo:using\n",
    "demo/advancement/ate.json": json.dumps({
        "criteria": {"c": {"trigger": "minecraft:consume_item", "conditions": {"item": {"items": "minecraft:stick"}}}}}),
}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_consumable_item_fires_using_item_each_tick_then_is_consumed(tmp_path, backend):
    """The 1.21.2+ right-click idiom: an item with a consumable component (Item.use ->
    Consumable.startConsuming: startUsingItem for consumeTicks = seconds x 20); each tick of use
    ServerPlayer.updateUsingItem fires using_item; at the end Consumable.onConsume awards
    used:<item>, consume_item, and the stack shrinks by one."""
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add uses dummy\n"
        "scoreboard objectives add used minecraft.used:minecraft.stick\n"
        "give @s stick[consumable={consume_seconds:0.25},custom_data={clicker:1b}] 2\n"
        "dummy @s use item\n"
        "assert not score @s uses matches 1..\n"        # the use ticks with the player, after the command
        "await delay 1\n"
        "assert score @s uses matches 1\n"
        "await delay 4\n"
        "assert score @s uses matches 5\n"
        "assert score @s used matches 1\n"
        "assert entity @s[advancements={demo:ate=true}]\n"
        "assert items entity @s weapon.mainhand stick[count=1]\n"
        "await delay 3\n"
        "assert score @s uses matches 5\n"), pack_format=57, files=USING, backend=backend)
    assert result.status == "passed", result.report()


def test_switching_away_from_the_used_item_stops_using_it(tmp_path):
    """LivingEntity.updatingUsingItem: the hand no longer holds the item: stopUsingItem."""
    result = run(tmp_path, "# @dummy\n" + (
        "scoreboard objectives add uses dummy\n"
        "give @s stick[consumable={consume_seconds:1},custom_data={clicker:1b}]\n"
        "dummy @s use item\n"
        "await delay 2\n"
        "dummy @s selectslot 2\n"
        "await delay 30\n"
        "assert score @s uses matches 2\n"
        "assert items entity @s hotbar.0 stick\n"), pack_format=57, files=USING)
    assert result.status == "passed", result.report()


def test_food_feeds_the_player_only_when_it_can_eat(tmp_path):
    """Consumable.canConsume -> Player.canEat: a full player cannot eat food that is not
    can_always_eat (FAIL: the command fails); FoodData.eat adds nutrition (max 20) and saturation
    (max the food level)."""
    result = run(tmp_path, "# @dummy\n" + (
        "give @s bread[consumable={consume_seconds:0},food={nutrition:5,saturation:6}] 2\n"
        "dummy @s use item\n"
        "assert items entity @s weapon.mainhand bread[count=2]\n"
        "data modify storage t x set value 0\n"
        "give @s cookie[consumable={consume_seconds:0},food={nutrition:2,saturation:0.5,can_always_eat:true}]\n"
        "dummy @s selectslot 2\n"
        "dummy @s use item\n"
        "assert not items entity @s hotbar.1 *\n"
        "assert data entity @s {foodLevel:20,foodSaturationLevel:5.5f}\n"), pack_format=57)
    assert result.status == "passed", result.report()
    assert "cannot use that item" in "\n".join(result.details)


def test_an_item_whose_use_is_not_modelled_makes_the_test_inconclusive(tmp_path):
    result = run(tmp_path, "# @dummy\ngive @s water_bucket\ndummy @s use item\nsucceed\n")
    assert (result.status, result.line) == ("inconclusive", 3), result.report()
    assert "using minecraft:water_bucket" in result.message


def test_a_potion_given_by_its_bare_id_saves_its_full_contents(tmp_path):
    """PotionContents.CODEC reads a bare potion id (Potion.CODEC) but encodes FULL_CODEC: the saved
    NBT has ``{potion: "minecraft:..."}``, which NBT tests match (gm4_potion_swords' assign_potion)."""
    result = run(tmp_path, (
        "dummy Alex spawn\n"
        "item replace entity Alex weapon.offhand with potion[potion_contents=\"long_slowness\"]\n"
        "assert entity @a[name=Alex,nbt={Inventory:[{id:\"minecraft:potion\",components:{\"minecraft:potion_contents\":"
        "{potion:\"minecraft:long_slowness\"}}}]}]\n"
        "assert items entity Alex weapon.offhand potion[potion_contents=\"minecraft:long_slowness\"]\n"))
    assert result.status == "passed", result.report()


def _picked_up(trigger: str, conditions: dict) -> str:
    return json.dumps({"criteria": {"c": {"trigger": f"minecraft:{trigger}", "conditions": conditions}}})


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_picking_up_a_thrown_item_fires_both_thrown_item_triggers(tmp_path, backend):
    """ItemEntity.playerTouch -> ServerPlayer.onItemPickup: the picker fires
    thrown_item_picked_up_by_player with the thrower (``Thrower``) as ``entity``, and
    LivingEntity.onItemPickup has the thrower, a player, fire thrown_item_picked_up_by_entity with
    the picker as ``entity`` (PickedUpItemTrigger: ``item`` tests the stack); an item with no
    thrower fires neither. The dummy picks up what it threw, so both land on it."""
    files = {
        "demo/advancement/by_player.json": _picked_up("thrown_item_picked_up_by_player",
                                                      {"item": {"items": "minecraft:stone"}}),
        "demo/advancement/by_player_dirt.json": _picked_up("thrown_item_picked_up_by_player",
                                                           {"item": {"items": "minecraft:dirt"}}),
        "demo/advancement/by_entity.json": _picked_up("thrown_item_picked_up_by_entity",
                                                      {"entity": {"type": "minecraft:player"}}),
    }
    result = run(tmp_path, "# @dummy\n" + (
        "execute at @s run summon item ~ ~ ~ {Item:{id:\"minecraft:dirt\",count:1},PickupDelay:1s}\n"
        "await delay 3\n"
        "assert items entity @s container.* dirt\n"
        "assert entity @s[advancements={demo:by_player=false,demo:by_player_dirt=false,demo:by_entity=false}]\n"
        "execute at @s run summon item ~ ~ ~ {Item:{id:\"minecraft:stone\",count:2},PickupDelay:1s,Tags:[\"thrown\"]}\n"
        "data modify entity @e[tag=thrown,limit=1] Thrower set from entity @s UUID\n"
        "await delay 3\n"
        "assert items entity @s container.* stone[count=2]\n"
        "assert entity @s[advancements={demo:by_player=true,demo:by_player_dirt=false,demo:by_entity=true}]\n"),
        files=files, backend=backend)
    assert result.status == "passed", result.report()
