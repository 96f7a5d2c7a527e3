"""Mining with an item: which tool may harvest a block, and what mining does to the tool.

- ``tool(stack, version) -> Tool | None``: the stack's ``tool`` component as a pack patched it, else
  the vanilla tool's (pickaxes, axes, shovels, hoes, swords and shears: ToolMaterial.
  applyToolProperties / applySwordProperties, ShearsItem.createToolProperties; the trident and the
  mace: no rules, 2 damage a block, as TridentItem.mineBlock before 1.20.5); before 1.20.5 the
  same rules from the tool's tier (DiggerItem.isCorrectToolForDrops: the ``needs_*_tool`` tags).
  None for an item that is no tool.
- ``Tool.correct_for_drops(block_id, resources)``: Tool.isCorrectForDrops (the first rule naming the
  block that says so); a vanilla block tag unknown without the game's data raises Unmodelled.
- ``mine_block(state, player, access, block_id)``: ItemStack.mineBlock -> Item.mineBlock: a tool
  counts ``minecraft.used:<item>`` and, unless the block breaks instantly (destroy time 0; shears
  also then, but not on fire), takes its ``damage_per_block``
  (ItemStack.hurtAndBreak: none for an unbreakable item or a creative player; the damage, and at
  the maximum the item breaks with ``minecraft.broken:<item>``), less what Unbreaking spares, with
  the ``item_durability_changed`` trigger (armour's wear is not modelled).

Not modelled (Unmodelled): the mining speed (PackTest's ``dummy mine`` breaks the block at once,
DummyCommand.mineBlock -> ServerPlayerGameMode.destroyBlock, so no pack sees it), the effects of
a pack's own enchantments and of a redefined Unbreaking (enchantment files are not read).

Sources (decompiled 1.21.x and 26.1): world/item/component/Tool.java (isCorrectForDrops),
ToolMaterial.java (incorrect_for_<tier>_tool tags), Item.java and ShearsItem.java (mineBlock),
ItemStack.java (mineBlock, hurtAndBreak, processDurabilityChange, applyDamage),
item/enchantment/Enchantments.java (UNBREAKING), effects/RemoveBinomial.java, advancements/critereon/
ItemDurabilityTrigger.java, DigDurabilityEnchantment.java before 1.21; before 1.20.5
DiggerItem.java and Tiers.java (tier levels).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from emulator.world import advancements, predicates, statistics
from emulator.world.errors import Unmodelled
from emulator.world.items import ItemStack, enchantment_level, enchantment_levels, set_component
from emulator.world.loot_context import in_ints
from emulator.world.nbt_ops import is_numeric, numeric_value
from mcfunction_parser.nbt import Compound, Int, List, String

F32 = np.float32
COMPONENTS_VERSION = (1, 20, 5)
ENCHANTMENT_EFFECTS_VERSION = (1, 21, 0)  # enchantments as data with effect components
_ARMOUR = ("_helmet", "_chestplate", "_leggings", "_boots")  # #enchantable/armor's vanilla members (with turtle_helmet)
TIERS = {"wooden": 0, "golden": 0, "stone": 1, "copper": 1, "iron": 2, "diamond": 3, "netherite": 4}
_MINEABLE = {"pickaxe": "pickaxe", "axe": "axe", "shovel": "shovel", "hoe": "hoe"}
# blocks whose destroy time is 0 (BlockBehaviour.Properties.instabreak()): a tool takes no damage
INSTANT_BREAK = frozenset("minecraft:" + n for n in (
    "short_grass grass fern dead_bush tall_grass large_fern seagrass tall_seagrass dandelion torchflower poppy "
    "blue_orchid allium azure_bluet red_tulip orange_tulip white_tulip pink_tulip oxeye_daisy cornflower "
    "wither_rose lily_of_the_valley sunflower lilac rose_bush peony brown_mushroom red_mushroom tnt torch "
    "wall_torch soul_torch soul_wall_torch redstone_torch redstone_wall_torch fire soul_fire redstone_wire "
    "repeater comparator wheat carrots potatoes beetroots sugar_cane lily_pad kelp kelp_plant end_rod "
    "slime_block honey_block scaffolding flower_pot structure_void bamboo_sapling warped_fungus crimson_fungus "
    "warped_roots crimson_roots nether_sprouts spore_blossom azalea flowering_azalea small_dripleaf "
    "hanging_roots frogspawn oak_sapling spruce_sapling birch_sapling jungle_sapling acacia_sapling "
    "cherry_sapling dark_oak_sapling pale_oak_sapling mangrove_propagule").split())


@dataclass(frozen=True)
class Rule:
    blocks: tuple[str, ...]  # ids and #tags
    correct_for_drops: bool | None


@dataclass(frozen=True)
class Tool:
    rules: tuple[Rule, ...]
    damage_per_block: int

    def correct_for_drops(self, block_id: str, resources) -> bool:
        """Tool.isCorrectForDrops: the first rule with ``correct_for_drops`` that names the block."""
        for rule in self.rules:
            if rule.correct_for_drops is not None and _names(rule.blocks, block_id, resources):
                return rule.correct_for_drops
        return False


def _names(blocks: tuple[str, ...], block_id: str, resources) -> bool:
    return any(resources.in_tag("block", b[1:], block_id) if b.startswith("#") else b == block_id for b in blocks)


def _vanilla(item_id: str, version) -> Tool | None:
    name = item_id.removeprefix("minecraft:")
    if name == "shears":
        return Tool((Rule(("minecraft:cobweb",), True),), 1)
    if name in ("trident", "mace"):  # TridentItem / MaceItem.createToolProperties: no rules, 2 a block
        return Tool((), 2)
    material, _, kind = name.rpartition("_")
    if material not in TIERS or kind not in (*_MINEABLE, "sword"):
        return None
    if kind == "sword":
        return Tool((Rule(("minecraft:cobweb",), True),), 2)
    mineable = Rule((f"#minecraft:mineable/{_MINEABLE[kind]}",), True)
    if tuple(version) >= COMPONENTS_VERSION:
        tier = "gold" if material == "golden" else material
        return Tool((Rule((f"#minecraft:incorrect_for_{tier}_tool",), False), mineable), 1)
    level = TIERS[material]  # DiggerItem.isCorrectToolForDrops: the needs_*_tool tags above the tier
    denied = tuple(f"#minecraft:needs_{t}_tool" for t, needed in (("diamond", 3), ("iron", 2), ("stone", 1))
                   if level < needed)
    return Tool(((Rule(denied, False),) if denied else ()) + (mineable,), 1)


def tool(stack: ItemStack, version) -> Tool | None:
    """The stack's tool: its patched ``tool`` component, else the vanilla item's."""
    if tuple(version) >= COMPONENTS_VERSION and ("minecraft:tool" in stack.patch or "!minecraft:tool" in stack.patch):
        tag = stack.component("minecraft:tool")
        return _from_component(tag) if isinstance(tag, Compound) else None
    return _vanilla(stack.id, version)


def _from_component(tag: Compound) -> Tool:
    rules = []
    for rule in tag.get("rules", List()):
        blocks = rule.get("blocks")
        listed = (str(blocks),) if isinstance(blocks, String) else tuple(str(b) for b in (blocks or ()))
        correct = rule.get("correct_for_drops")
        rules.append(Rule(tuple(b if b.startswith("#") or ":" in b else "minecraft:" + b for b in listed),
                          bool(numeric_value(correct)) if is_numeric(correct) else None))
    damage = tag.get("damage_per_block")
    return Tool(tuple(rules), int(numeric_value(damage)) if is_numeric(damage) else 1)


def mine_block(state, player, access, block_id: str) -> None:
    """ItemStack.mineBlock for the main hand's stack (``access``) after it mined ``block_id``."""
    stack = access.get()
    found = tool(stack, state.version)
    if found is None:
        return  # Item.mineBlock: no tool, nothing happens
    statistics.award(state, player, statistics.stat_name("used", stack.id))
    shears = stack.id == "minecraft:shears"
    if found.damage_per_block > 0 and (block_id not in INSTANT_BREAK if not shears else "fire" not in block_id):
        hurt_and_break(state, player, access, found.damage_per_block)


def wear_at_random(stack: ItemStack, rng, version) -> None:
    """A dying mob's equipment dropped by chance (Mob.dropCustomDeathLoot): a damageable item
    (ItemStack.isDamageableItem: max_damage, not unbreakable) gets damage max - nextInt(1 +
    nextInt(max(max - 3, 1))), clamped to [0, max] (setDamageValue)."""
    max_damage = stack.component("minecraft:max_damage")
    if not is_numeric(max_damage) or stack.component("minecraft:unbreakable") is not None or (stack.tag or {}).get("Unbreakable"):
        return
    top = int(numeric_value(max_damage))
    _set_damage(stack, min(max(top - rng.randrange(1 + rng.randrange(max(top - 3, 1))), 0), top), version)


def _set_damage(stack: ItemStack, damage: int, version) -> None:
    """The ``damage`` component, or the ``Damage`` tag before components."""
    if tuple(version) >= COMPONENTS_VERSION:
        set_component(stack, "minecraft:damage", Int(damage))
    else:
        stack.tag = stack.tag if stack.tag is not None else Compound()
        stack.tag["Damage"] = Int(damage)


def hurt_and_break(state, player, access, amount: int) -> None:
    """ItemStack.hurtAndBreak: nothing for an item that takes no damage or a player with infinite
    materials; the damage less what Unbreaking spares (processDurabilityChange), then
    ``item_durability_changed`` with the damage to come, the new ``damage`` and, at the maximum,
    the item broken (``minecraft.broken:<item>``)."""
    stack = access.get()
    max_damage = stack.component("minecraft:max_damage")
    if (not is_numeric(max_damage) or stack.component("minecraft:unbreakable") is not None
            or (stack.tag or {}).get("Unbreakable") or player.gamemode == "creative"):
        return
    if amount > 0:
        amount -= _spared(state, stack, amount)
        if amount <= 0:
            return
    components = tuple(state.version) >= COMPONENTS_VERSION
    damage = stack.component("minecraft:damage") if components else (stack.tag or {}).get("Damage")
    old_damage = int(numeric_value(damage)) if is_numeric(damage) else 0
    new_damage = old_damage + amount
    advancements.trigger(state, player, "item_durability_changed",
                         _durability_test(stack, int(numeric_value(max_damage)), old_damage, new_damage))
    _set_damage(stack, new_damage, state.version)
    if new_damage >= int(numeric_value(max_damage)):
        stack.count -= 1
        statistics.award(state, player, statistics.stat_name("broken", stack.id))
    access.set(stack)


def _spared(state, stack: ItemStack, amount: int) -> int:
    """The damage points Unbreaking spares, drawn from the emulator's seeded random (the game draws
    from the level's). From 1.21 its item_damage effect (Enchantments.UNBREAKING: remove_binomial,
    each point spared with chance level / (level + 1), armour 2 level / (5 level + 5), float math);
    before, DigDurabilityEnchantment.shouldIgnoreDurabilityDrop (armour first passes 60 %, then
    nextInt(level + 1) > 0)."""
    if tuple(state.version) >= ENCHANTMENT_EFFECTS_VERSION:
        foreign = [e for e in enchantment_levels(stack) if not e.startswith("minecraft:")]
        if foreign or "minecraft:unbreaking" in state.resources.redefined_enchantments:
            raise Unmodelled(f"the item_damage effects of {(foreign or ['a redefined minecraft:unbreaking'])[0]} "
                             "(enchantment files are not read)")
    level = _unbreaking_level(state, stack)
    if level <= 0:
        return 0
    random = state.resources.random
    armour = stack.id.endswith(_ARMOUR)
    if tuple(state.version) >= ENCHANTMENT_EFFECTS_VERSION:
        chance = F32(2 * level) / F32(10 + 5 * (level - 1)) if armour else F32(level) / F32(2 + (level - 1))
        return sum(F32(random.random()) < chance for _ in range(amount))
    return sum(not (armour and random.random() < 0.6) and random.randrange(level + 1) > 0 for _ in range(amount))


def _unbreaking_level(state, stack: ItemStack) -> int:
    if tuple(state.version) >= COMPONENTS_VERSION:
        return enchantment_level(stack, "minecraft:unbreaking")
    for entry in (stack.tag or {}).get("Enchantments") or ():
        if isinstance(entry, Compound) and str(entry.get("id", "")).removeprefix("minecraft:") == "unbreaking":
            return int(numeric_value(entry.get("lvl", Int(0))))
    return 0


def _durability_test(stack: ItemStack, max_damage: int, old_damage: int, new_damage: int):
    """ItemDurabilityTrigger: ``item`` (the stack before the damage), ``durability`` (what is left
    after it), ``delta`` (the old damage less the new: negative)."""
    def test(conditions: dict, ctx) -> bool:
        return ((conditions.get("item") is None or predicates.item_matches(conditions["item"], ctx, stack))
                and (conditions.get("durability") is None
                     or in_ints(conditions["durability"], max_damage - new_damage))
                and (conditions.get("delta") is None or in_ints(conditions["delta"], old_damage - new_damage)))
    return test
