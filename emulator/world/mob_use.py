"""A player using a mob (Mob.interact) or using its held item on a living entity
(ItemStack.interactLivingEntity), with what a datapack observes: the mob's name, saddle and
rider, the milk bucket, the item spent, the ``started_riding`` criterion.

- ``interact(state, player, hand, mob) -> str``: Mob.interact: ``"consume"`` or ``"pass"``.
- ``item_on_living(state, player, hand, entity) -> str``: Item.interactLivingEntity, the held
  item's own use when the entity's passed (Player.interactOn).

Mob.interact, in order: a name tag with a name names the mob (NameTagItem: ``CustomName``,
``PersistenceRequired``, one tag spent); a spawn egg spawns a baby (not modelled); a leash (a leashed
mob, a lead in hand: not modelled); then the mob's own mobInteract:
- pig (Pig.mobInteract): not holding its food (``#minecraft:pig_food``), saddled (``Saddle``), with
  no rider and not sneaking, the player mounts it; else the breeding of Animal.mobInteract, then a
  saddle saddles it (SaddleItem: an adult without one; ``Saddle:1b``, one saddle spent);
- cow (Cow.mobInteract): a bucket on an adult fills with milk (ItemUtils.createFilledResult: one
  bucket spent, the milk bucket in its place, or added to the inventory (dropped when full) when
  more buckets are left; a creative player keeps the bucket and gets a milk bucket if it has none);
  else breeding with ``#minecraft:cow_food``;
- sheep (Sheep.mobInteract): shears shear one ready for it (``Sheared:1b``, 1 to 3 wool of its
  colour dropped, the count drawn from the emulator's random; the shears worn by one), or
  consume the use on one that is not; from 1.21.2 the wool's loot table is not modelled;
- villagers and wandering traders (Villager / WanderingTrader.mobInteract): the use counts
  ``minecraft.custom:minecraft.talked_to_villager`` (main hand) and is consumed; with offers (saved
  ``Offers``) the trading menu opens, closing the player's open container; a baby villager just
  refuses. The first trades drawn at random (a trading profession or a wandering trader without
  saved ``Offers``), special prices (gossip, Hero of the Village) and using a merchant again after
  its menu opened (whether it still trades) are not modelled;
- breeding (Animal.mobInteract): food given to an adult at age 0 not in love, or to a baby, is not
  modelled (what follows over the next ticks: love counting down, the breed goal, the baby's age);
  to an adult that cannot fall in love it passes;
- mobs whose mobInteract is Mob's own (zombies, skeletons, spiders ...): pass.
Any other mob's mobInteract (horses, wolves, cats ...) raises
Unmodelled. A creative player keeps what a use took from its hand (Player.interactOn restores the
count; the item's own use works on a copy).

The ``player_interacted_with_entity`` criterion fires in the network handler, not for a PackTest
dummy (emulator.world.entity_use). The game events and sounds are not observable by a pack.

Sources (decompiled 1.21): world/entity/Mob.java (interact, checkAndHandleImportantInteractions),
Entity.java (interact: Leashable; startRiding: START_RIDING_TRIGGER; positionRider),
world/entity/player/Player.java (interactOn), server/level/ServerPlayer.java (startRiding),
world/entity/animal/Pig.java, Cow.java, Sheep.java (mobInteract, shear), Animal.java (mobInteract,
setInLove), world/entity/npc/Villager.java, WanderingTrader.java (mobInteract), AbstractVillager.java (getOffers),
world/item/NameTagItem.java, SaddleItem.java, ItemUtils.java (createFilledResult),
world/entity/EntityType.java (pig: passengerAttachments; emulator.world.relations.position_rider).
"""
from __future__ import annotations

from emulator.world import block_use, inventories, items, living, relations, statistics, tools
from emulator.world.entities import TextTag
from emulator.world.errors import Unmodelled
from emulator.world.id_families import COLOURS
from emulator.world.items import ItemStack
from emulator.world import player_actions
from emulator.world.player_actions import MAIN, hand_slot
from mcfunction_parser.nbt import Byte, String

SADDLE_EQUIPMENT_VERSION = (1, 21, 5)  # 25w02a: a saddle is worn in the ``saddle`` equipment slot
# mobs without a mobInteract of their own (Mob.mobInteract passes)
PLAIN_MOBS = frozenset("minecraft:" + n for n in (
    "zombie husk drowned zombified_piglin skeleton stray wither_skeleton spider cave_spider silverfish endermite "
    "blaze enderman ghast witch vindicator pillager evoker illusioner ravager vex phantom guardian elder_guardian "
    "slime magma_cube shulker warden breeze wither ender_dragon bat squid glow_squid").split())


def _held(state, player, hand: str):
    access = inventories.entity_slot(player, hand_slot(hand), state.version)
    return access, access.get()


def _spend(state, player, hand: str, count: int = 1) -> None:
    """The use takes ``count`` items from the hand; a creative player keeps them (Player.interactOn)."""
    if player.gamemode == "creative":
        return
    access, stack = _held(state, player, hand)
    stack.count -= count
    access.set(stack)


def interact(state, player, hand: str, mob) -> str:
    """Mob.interact (see the module's doc)."""
    if not mob.alive:
        return "pass"
    _, held = _held(state, player, hand)
    if held.id == "minecraft:name_tag" and _name_tag(state, player, hand, mob) == "consume":
        return "consume"
    if held.id.endswith("_spawn_egg"):
        raise Unmodelled(f"using {held.id} on {mob.type} (SpawnEggItem.spawnOffspringFromSpawnEgg)")
    if mob.data.get("leash") is not None or mob.data.get("Leash") is not None:
        raise Unmodelled(f"using a leashed {mob.type} (Leashable.dropLeash)")
    if held.id == "minecraft:lead":
        raise Unmodelled(f"leashing {mob.type} (Leashable.setLeashedTo)")
    own = MOB_INTERACTS.get(mob.type)
    if own is not None:
        return own(state, player, hand, mob)
    if mob.type in PLAIN_MOBS:
        return "pass"
    raise Unmodelled(f"using {mob.type} (its mobInteract is not modelled: only pigs, cows, sheep, villagers, "
                     "wandering traders and mobs without one)")


def item_on_living(state, player, hand: str, entity) -> str:
    """Item.interactLivingEntity of the held item (NameTagItem, SaddleItem; DyeItem on a sheep is
    not modelled); any other item passes."""
    _, held = _held(state, player, hand)
    if held.id == "minecraft:name_tag":
        return _name_tag(state, player, hand, entity)
    if held.id == "minecraft:saddle":
        return _saddle(state, player, hand, entity)
    if held.id.endswith("_dye") and entity.type == "minecraft:sheep":
        raise Unmodelled("dyeing a sheep (DyeItem.interactLivingEntity)")
    return "pass"


def _name_tag(state, player, hand: str, entity) -> str:
    """NameTagItem.interactLivingEntity: a tag with a ``custom_name`` names any living entity but a
    player (a mob is then kept: ``PersistenceRequired``) and is spent; without one it passes."""
    _, held = _held(state, player, hand)
    name = held.component("minecraft:custom_name")
    if name is None and tuple(state.version) < items.COMPONENTS_VERSION:
        display = (held.tag or {}).get("display")
        name = display.get("Name") if display is not None else None
    if name is None or entity.is_player:
        return "pass"
    if entity.alive:
        entity.custom_name = str(name) if isinstance(name, String) else TextTag(name)
        if entity.type != "minecraft:armor_stand":
            entity.data["PersistenceRequired"] = Byte(1)
        _spend(state, player, hand)
    return "consume"


def _saddled(state, mob) -> bool:
    if tuple(state.version) >= SADDLE_EQUIPMENT_VERSION:
        raise Unmodelled(f"a saddle on {mob.type} worn in the saddle slot (1.21.5+)")
    return bool(mob.data.get("Saddle"))


def _saddle(state, player, hand: str, mob) -> str:
    """SaddleItem.interactLivingEntity: an alive, saddleable (adult pig or strider) mob without a
    saddle takes one; horses are not modelled."""
    if mob.type not in ("minecraft:pig", "minecraft:strider"):
        if mob.type.endswith(("horse", "donkey", "mule", "camel")):
            raise Unmodelled(f"saddling {mob.type} (AbstractHorse)")
        return "pass"
    if not mob.alive or _saddled(state, mob) or living.is_baby(mob):
        return "pass"
    mob.data["Saddle"] = Byte(1)
    _spend(state, player, hand)
    return "consume"


def _in_tag(state, tag: str, stack) -> bool:
    return not stack.is_empty and state.resources.in_tag("item", tag, stack.id)


def _breed(state, player, hand: str, mob, food_tag: str) -> str:
    """Animal.mobInteract: food given to an adult at age 0 not in love (``InLove`` 600, one item
    spent) or to a baby (AgeableMob.ageUp) starts what the following ticks carry on (love counting
    down, the breed goal finding a partner, the baby's age): not modelled. Food to an adult that
    cannot fall in love passes, as does anything else."""
    _, held = _held(state, player, hand)
    if not _in_tag(state, food_tag, held):
        return "pass"
    age = int(mob.data.get("Age", 0))
    if age == 0 and int(mob.data.get("InLove", 0)) <= 0:
        raise Unmodelled(f"breeding {mob.type} (InLove counting down and the breed goal: Animal.aiStep, BreedGoal)")
    if age < 0:
        raise Unmodelled(f"feeding a baby {mob.type} (AgeableMob.ageUp and its age counting up)")
    return "pass"


def _pig(state, player, hand: str, pig) -> str:
    """Pig.mobInteract (see the module's doc)."""
    _, held = _held(state, player, hand)
    food = _in_tag(state, "minecraft:pig_food", held)
    if not food and _saddled(state, pig) and not relations.passengers_of(pig) and not player.sneaking:
        relations.mount(state, player, pig)
        return "consume"
    result = _breed(state, player, hand, pig, "minecraft:pig_food")
    if result == "consume":
        return result
    return _saddle(state, player, hand, pig) if held.id == "minecraft:saddle" else "pass"


def _cow(state, player, hand: str, cow) -> str:
    """Cow.mobInteract: a bucket milks an adult cow; else Animal's breeding."""
    access, held = _held(state, player, hand)
    if held.id == "minecraft:bucket" and not living.is_baby(cow):
        access.set(player_actions.filled_result(state, player, held, ItemStack("minecraft:milk_bucket", 1)))
        return "consume"
    return _breed(state, player, hand, cow, "minecraft:cow_food")


SHEARING_LOOT_VERSION = (1, 21, 2)  # 24w33a: a sheep's wool comes from its shearing loot table


def _sheep(state, player, hand: str, sheep) -> str:
    """Sheep.mobInteract: shears on a sheep ready for shearing (alive, not ``Sheared``, adult)
    shear it (Sheep.shear: ``Sheared:1b``, 1 to 3 wool of its ``Color`` dropped one above its feet,
    each with the item's own motion plus a little random push, the count and pushes drawn from the
    emulator's random, not the sheep's) and wear by one; on a sheep not ready they consume the use.
    From 1.21.2 the wool comes from the game's shearing loot tables (not modelled). Else breeding
    (``#minecraft:sheep_food``)."""
    access, held = _held(state, player, hand)
    if held.id != "minecraft:shears":
        return _breed(state, player, hand, sheep, "minecraft:sheep_food")
    if not sheep.alive or sheep.data.get("Sheared") or living.is_baby(sheep):
        return "consume"
    if tuple(state.version) >= SHEARING_LOOT_VERSION:
        raise Unmodelled("shearing a sheep (its shearing loot table, 1.21.2+)")
    sheep.data["Sheared"] = Byte(1)
    rng = state.resources.random
    wool = ItemStack(f"minecraft:{COLOURS[int(sheep.data.get('Color', 0)) & 15]}_wool", 1)
    x, y, z = sheep.pos
    for _ in range(1 + rng.randrange(3)):
        item = inventories.drop_item(state.entities, (x, y + 1.0, z), wool.copy(), state.version, rng,
                                     dimension=sheep.dimension)
        mx, my, mz = item.motion
        item.motion = (mx + (rng.random() - rng.random()) * 0.1, my + rng.random() * 0.05,
                       mz + (rng.random() - rng.random()) * 0.1)
    tools.hurt_and_break(state, player, access, 1)
    return "consume"


# professions with no trades (VillagerTrades.TRADES has none for them)
_NO_TRADES = ("minecraft:none", "minecraft:nitwit")


def _offers_empty(mob) -> bool:
    """AbstractVillager.getOffers().isEmpty(): the saved ``Offers``' recipes; without any, a
    villager of a trading profession (and any wandering trader) draws its first trades at random
    (updateTrades), which is not modelled."""
    offers = mob.data.get("Offers")
    if offers is not None:
        return not offers.get("Recipes")
    data = mob.data.get("VillagerData")
    profession = str(data.get("profession", "minecraft:none")) if data is not None else "minecraft:none"
    profession = profession if ":" in profession else "minecraft:" + profession
    if mob.type == "minecraft:villager" and profession in _NO_TRADES:
        return True
    raise Unmodelled(f"the first trades of {mob.type} (updateTrades: drawn at random)")


def _merchant(state, player, hand: str, mob) -> str:
    """Villager / WanderingTrader.mobInteract: a baby villager refuses (consumed; a baby trader
    passes); else ``minecraft.custom:minecraft.talked_to_villager`` for the main hand; with no
    offers the use is consumed, with offers the trading menu opens (startTrading: the player's
    open container closes first; special prices from gossip or Hero of the Village are not
    modelled). A merchant whose menu a use opened is trading until the menu closes, which is not
    followed here: using it again is not modelled."""
    _, held = _held(state, player, hand)
    if held.id == "minecraft:villager_spawn_egg":
        raise Unmodelled(f"using a villager spawn egg on {mob.type}")
    if state.trading.get(mob) is not None:  # AbstractVillager.tradingPlayer (not saved)
        raise Unmodelled(f"using {mob.type} after its trading menu opened (whether it is still trading)")
    if living.is_baby(mob):
        return "consume" if mob.type == "minecraft:villager" else "pass"
    empty = _offers_empty(mob)
    if not empty and mob.type == "minecraft:villager" and (
            mob.data.get("Gossips") or living.effect_amplifier(player, "minecraft:hero_of_the_village") is not None):
        raise Unmodelled("a villager's special prices (Villager.updateSpecialPrices: gossip, Hero of the Village)")
    if hand == MAIN:
        statistics.award(state, player, statistics.stat_name("custom", "talked_to_villager"))
    if not empty:
        block_use.close_menu(state, player)  # Player.openMenu closes the open container
        state.trading[mob] = player
    return "consume"


MOB_INTERACTS = {"minecraft:pig": _pig, "minecraft:cow": _cow, "minecraft:villager": _merchant,
                 "minecraft:wandering_trader": _merchant, "minecraft:sheep": _sheep}
