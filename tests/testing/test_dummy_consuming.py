"""Dummies eating and drinking the game's own items (emulator.world.consumables): the vanilla
foods' nutrition and saturation (Foods: FoodProperties.Builder.build, saturation = nutrition x
modifier x 2), their use time (Consumables: 1.6 s, dried kelp 0.8 s, honey 2 s), their effects
(Consumables.GOLDEN_APPLE ...), potions (PotionContents.onConsume), milk
(ClearAllStatusEffectsConsumeEffect), honey (RemoveStatusEffectsConsumeEffect) and the use remainder
(ItemStack.applyAfterUseComponentSideEffects -> UseRemainder.convertIntoRemainder)."""
import pytest

from tests.conftest import OPEN_AREA
from tests.testing.test_dummy_hands import run

@pytest.mark.parametrize("pack_format", [26, 48, 57, 61])
def test_a_golden_apple_feeds_a_full_player_and_gives_its_effects(tmp_path, pack_format):
    """Foods.GOLDEN_APPLE: 4 nutrition, modifier 1.2 (saturation 9.6), always edible;
    Consumables.GOLDEN_APPLE: regeneration II 100 ticks, absorption 2400 ticks; eaten over 32 ticks
    (1.6 s), then used:golden_apple and one apple fewer. Before 1.20.5 (format 26) the same from
    FoodProperties and Item.getUseDuration."""
    result = run(tmp_path, "# @dummy\n" + OPEN_AREA + (
        "scoreboard objectives add ate minecraft.used:minecraft.golden_apple\n"
        "give @s golden_apple 3\n"
        "dummy @s use item\n"
        "await delay 31\n"
        "assert not score @s ate matches 1..\n"
        "await delay 1\n"
        "assert score @s ate matches 1\n"
        "assert data entity @s SelectedItem{id:\"minecraft:golden_apple\",%s}\n"
        "assert data entity @s {foodLevel:20,foodSaturationLevel:14.6f}\n"
        "assert data entity @s active_effects[{id:\"minecraft:regeneration\",amplifier:1b}]\n"
        "assert data entity @s active_effects[{id:\"minecraft:absorption\",amplifier:0b}]\n"
        "execute store result score #d ate run data get entity @s "
        "active_effects[{id:\"minecraft:absorption\"}].duration\n"
        "assert score #d ate matches 2400\n") % ("Count:2b" if pack_format < 41 else "count:2"),
        pack_format=pack_format)
    assert result.status == "passed", result.report()


def test_a_full_player_cannot_eat_bread(tmp_path):
    """Player.canEat: bread is not always edible (Foods.BREAD): the use fails, the command fails."""
    result = run(tmp_path, "# @dummy\n" + OPEN_AREA + "give @s bread\ndummy @s use item\nawait delay 40\n"
                           "assert items entity @s weapon.mainhand bread\n", pack_format=61)
    assert result.status == "passed", result.report()
    assert "cannot use that item" in "\n".join(result.details)


def test_dried_kelp_is_eaten_in_16_ticks(tmp_path):
    """Consumables.DRIED_KELP: consume_seconds 0.8 (16 ticks); the using_item trigger fires each
    tick of the use (ServerPlayer.updateUsingItem). A creative player can always eat
    (Player.canEat: invulnerable) and keeps the item."""
    files = {"demo/advancement/using.json": '{"criteria":{"c":{"trigger":"minecraft:using_item"}},'
                                            '"rewards":{"function":"demo:using"}}',
             "demo/function/using.mcfunction": "scoreboard players add @s uses 1\nadvancement revoke @s only demo:using\n"}
    result = run(tmp_path, "# @dummy\n" + OPEN_AREA + (
        "scoreboard objectives add uses dummy\n"
        "gamemode creative @s\n"
        "give @s dried_kelp 2\n"
        "dummy @s use item\n"
        "await delay 16\n"
        "assert score @s uses matches 16\n"
        "await delay 5\n"
        "assert score @s uses matches 16\n"
        "assert items entity @s weapon.mainhand dried_kelp[count=2]\n"), pack_format=61, files=files)
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("pack_format, potion", [(26, 'potion{Potion:"minecraft:swiftness"}'),
                                                 (41, 'potion[potion_contents={potion:"minecraft:swiftness"}]'),
                                                 (61, 'potion[potion_contents="minecraft:strong_swiftness"]')])
def test_drinking_a_potion_gives_its_effects_and_a_glass_bottle(tmp_path, pack_format, potion):
    """Potions.SWIFTNESS: speed 3600 ticks (strong: 1800 ticks, amplifier 1); PotionItem: drunk over
    32 ticks, consume_item fires, the potion becomes a glass bottle (Items.POTION
    usingConvertsTo(GLASS_BOTTLE); PotionItem.finishUsingItem before 1.21.2)."""
    strong = "strong" in potion
    files = {"demo/advancement/drank.json": '{"criteria":{"c":{"trigger":"minecraft:consume_item",'
                                            '"conditions":{"item":{"items":"minecraft:potion"}}}}}'}
    if pack_format < 48:
        files["demo/advancements/drank.json"] = files.pop("demo/advancement/drank.json").replace(
            '"items":"minecraft:potion"', '"items":["minecraft:potion"]')
    result = run(tmp_path, "# @dummy\n" + OPEN_AREA + (
        "scoreboard objectives add t dummy\n"
        f"give @s {potion}\n"
        "dummy @s use item\n"
        "await delay 32\n"
        "assert data entity @s SelectedItem{id:\"minecraft:glass_bottle\"}\n"
        f"assert data entity @s active_effects[{{id:\"minecraft:speed\",amplifier:{int(strong)}b}}]\n"
        "execute store result score #d t run data get entity @s active_effects[0].duration\n"
        f"assert score #d t matches {1800 if strong else 3600}\n"
        "assert entity @s[advancements={demo:drank=true}]\n"), pack_format=pack_format, files=files)
    assert result.status == "passed", result.report()


def test_a_healing_potion_heals_at_once_and_milk_clears_effects(tmp_path):
    """PotionContents.applyToLivingEntity: instantaneous effects act at once (HealOrHarmMobEffect:
    4 << amplifier); Consumables.MILK_BUCKET: clear_all_effects, the bucket returned."""
    result = run(tmp_path, "# @dummy\n# @timeout 200\n" + OPEN_AREA + (
        "gamerule naturalRegeneration false\n"  # FoodData.tick would heal the hurt dummy as well
        "await delay 60\n"  # 1.21.4: no damage before its client would have loaded (ServerPlayer.isInvulnerableTo)
        "damage @s 6\n"
        "give @s potion[potion_contents=\"minecraft:healing\"]\n"
        "dummy @s use item\n"
        "await delay 32\n"
        "assert data entity @s {Health:18f}\n"
        "assert not data entity @s active_effects\n"  # applied at once, never added
        "effect give @s speed 100\n"
        "effect give @s poison 100\n"
        "item replace entity @s weapon.mainhand with milk_bucket\n"
        "dummy @s use item\n"
        "await delay 32\n"
        "assert not data entity @s active_effects\n"
        "assert items entity @s weapon.mainhand bucket\n"), pack_format=61)
    assert result.status == "passed", result.report()


def test_honey_cures_poison_and_a_stack_of_stew_gives_its_bowl_to_the_inventory(tmp_path):
    """Consumables.HONEY_BOTTLE: 2 s, remove_effects poison, always edible; a stack that is not
    emptied keeps the hand and the remainder goes to the inventory
    (ServerPlayer.handleExtraItemsCreatedOnUse)."""
    result = run(tmp_path, "# @dummy\n" + OPEN_AREA + (
        "effect give @s poison 100\n"
        "effect give @s speed 100\n"
        "give @s honey_bottle 2\n"
        "dummy @s use item\n"
        "await delay 39\n"
        "assert data entity @s active_effects[{id:\"minecraft:poison\"}]\n"
        "await delay 1\n"
        "assert not data entity @s active_effects[{id:\"minecraft:poison\"}]\n"
        "assert data entity @s active_effects[{id:\"minecraft:speed\"}]\n"
        "assert items entity @s weapon.mainhand honey_bottle[count=1]\n"
        "assert items entity @s hotbar.1 glass_bottle\n"), pack_format=61)
    assert result.status == "passed", result.report()


def test_a_creative_dummy_keeps_the_potion(tmp_path):
    """ItemStack.consume and UseRemainder: a player with infinite materials keeps the stack and gets
    no remainder."""
    result = run(tmp_path, "# @dummy\n" + OPEN_AREA + "gamemode creative @s\ngive @s potion[potion_contents=\"minecraft:luck\"]\n"
                           "dummy @s use item\nawait delay 32\nassert items entity @s weapon.mainhand potion\n"
                           "assert data entity @s active_effects[{id:\"minecraft:luck\"}]\n"
                           "assert not items entity @s hotbar.1 *\n", pack_format=61)
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("pack_format", [48, 61])
def test_chorus_fruit_teleports_the_eater_onto_ground_nearby_and_cools_down(tmp_path, pack_format):
    """Consumables.CHORUS_FRUIT (1.21.2+: teleport_randomly, use_cooldown 1 s; before, ChorusFruitItem.
    finishUsingItem and addCooldown(item, 20)): LivingEntity.randomTeleport lands it on the first
    block below that blocks motion, within 8 blocks in x and z, in a free spot; a second fruit
    right after passes (cooling down). The spot comes from the seeded random."""
    result = run(tmp_path, "# @dummy\n" + OPEN_AREA + (
        "fill ~-8 ~-1 ~-8 ~8 ~-1 ~8 stone\n"
        "give @s chorus_fruit 2\n"
        "dummy @s use item\n"
        "await delay 32\n"
        "assert not entity @s[x=0.5,y=1,z=0.5,distance=..0.01]\n"
        "assert entity @s[x=-7.5,y=-7,z=-7.5,dx=16,dy=16,dz=16]\n"
        "execute at @s if block ~ ~-1 ~ air run fail \"nothing below\"\n"
        "execute at @s unless block ~ ~ ~ air run fail \"inside a block\"\n"
        "dummy @s use item\n"
        "assert items entity @s weapon.mainhand chorus_fruit[count=1]\n"
        "fail \"end\"\n"), pack_format=pack_format)
    assert (result.status, result.message) == ("failed", "end"), result.report()
    assert "\n".join(result.details).count("cannot use that item") == 1


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_use_cooldown_makes_the_next_uses_of_its_group_pass_until_it_ends(tmp_path, backend):
    """ItemStack.use -> applyAfterUseComponentSideEffects -> UseCooldown.apply: the group (the
    cooldown_group, else the item) cools down Math.round(seconds * 20) ticks; meanwhile
    ServerPlayerGameMode.useItem passes (ItemCooldowns.isOnCooldown), also for another item of the
    group, and useItemOn uses the block without the item (no placement)."""
    result = run(tmp_path, "# @dummy\n" + OPEN_AREA + (
        "scoreboard objectives add ate minecraft.used:minecraft.stick\n"
        "scoreboard objectives add placed minecraft.used:minecraft.stone\n"
        "give @s stick[consumable={consume_seconds:0},use_cooldown={seconds:1,cooldown_group:\"demo:g\"}] 4\n"
        "dummy @s use item\n"
        "assert score @s ate matches 1\n"
        "dummy @s use item\n"                            # cooling down: passes
        "assert score @s ate matches 1\n"
        "item replace entity @s weapon.offhand with stone[use_cooldown={seconds:5,cooldown_group:\"demo:g\"}]\n"
        "setblock ~3 ~ ~ dirt\n"
        "dummy @s swap\n"
        "dummy @s use block ~3 ~ ~ up\n"                 # the stone is of the same group: not placed
        "assert block ~3 ~1 ~ air\n"
        "dummy @s swap\n"
        "await delay 19\n"
        "dummy @s use item\n"
        "assert score @s ate matches 1\n"
        "await delay 1\n"                                # 20 ticks after the use
        "dummy @s use item\n"
        "assert score @s ate matches 2\n"
        "assert items entity @s weapon.mainhand stick[count=2]\n"
        "fail \"end\"\n"), pack_format=61, backend=backend)
    assert (result.status, result.message) == ("failed", "end"), result.report()
    assert "\n".join(result.details).count("cannot use that item") == 2