"""The predicate engine (emulator.world.predicates) against the game's rules, each pinned to its
source (decompiled 1.21, net/minecraft/world/level/storage/loot/predicates and
advancements/critereon)."""
from __future__ import annotations

import pytest

from emulator.world import inventories, loot, predicates, recipes
from emulator.world.blocks import BlockSpec, parse_block, with_defaults
from emulator.world.entities import entity_nbt
from emulator.world.light import emission, light_block
from emulator.world.errors import Unmodelled
from emulator.world.items import ItemStack
from emulator.world.loot_context import DamageSource, LootContext, in_ints, in_range
from emulator.world.predicates import test as holds
from emulator.world.resources import Resources
from emulator.world.state import WorldState
from mcfunction_parser.pack.conditions import parse_inline
from mcfunction_parser.pack.registry_tags import RegistryTag
from mcfunction_parser.nbt import Byte, Compound, Int, List, String


@pytest.fixture
def state():
    return WorldState()


def ctx(state, **kw):
    return LootContext(state, kw.pop("origin", (0.0, 0.0, 0.0)), **kw)


def test_all_of_empty_is_true_any_of_empty_is_false(state):
    # AllOfCondition / AnyOfCondition: Util.allOf([]) is always true, Util.anyOf([]) always false
    assert holds({"condition": "all_of", "terms": []}, ctx(state))
    assert not holds({"condition": "any_of", "terms": []}, ctx(state))
    assert holds({"condition": "inverted", "term": {"condition": "any_of", "terms": []}}, ctx(state))
    assert holds([], ctx(state))  # a predicate file's list: every condition must hold


def test_reference_unknown_or_looping_is_false(state):
    # ConditionReference.test: an unknown id or a predicate reaching itself logs and is false
    state.resources = Resources(predicates={"t:self": {"condition": "reference", "name": "t:self"}})
    assert not holds({"condition": "reference", "name": "t:none"}, ctx(state))
    assert not predicates.test_predicate("t:self", ctx(state))


def test_entity_properties_needs_the_entity_unless_no_predicate(state):
    # LootItemEntityPropertyCondition.test: no predicate is true; EntityPredicate.matches(null) false
    assert holds({"condition": "entity_properties", "entity": "this"}, ctx(state))
    assert not holds({"condition": "entity_properties", "entity": "this", "predicate": {}}, ctx(state))
    pig = state.entities.summon("minecraft:pig", (1.0, 2.0, 3.0))
    assert holds({"condition": "entity_properties", "entity": "this", "predicate": {}}, ctx(state, this=pig))
    assert not holds({"condition": "entity_properties", "entity": "attacker", "predicate": {}}, ctx(state, this=pig))


def test_distance_compares_float_differences(state):
    # DistancePredicate.matches: (float) differences; x/y/z on absolute values, absolute squared
    pig = state.entities.summon("minecraft:pig", (3.0, 4.0, 0.0))
    at_origin = ctx(state, this=pig)
    near = {"condition": "entity_properties", "entity": "this", "predicate": {"distance": {"absolute": {"max": 5}}}}
    assert holds(near, at_origin)
    near["predicate"]["distance"]["absolute"]["max"] = 4.99
    assert not holds(near, at_origin)
    assert holds({"condition": "entity_properties", "entity": "this",
                 "predicate": {"distance": {"x": {"min": 3, "max": 3}, "horizontal": {"max": 3}}}}, at_origin)


def test_entity_scores_and_value_check(state):
    # EntityScoresCondition: a missing objective or unset score fails; IntRange bounds inclusive
    pig = state.entities.summon("minecraft:pig", (0.0, 0.0, 0.0))
    state.scoreboard.add_objective("hp")
    scores = {"condition": "entity_scores", "entity": "this", "scores": {"hp": {"min": 1, "max": 5}}}
    assert not holds(scores, ctx(state, this=pig))
    state.scoreboard.set(pig.score_holder, "hp", 5)
    assert holds(scores, ctx(state, this=pig))
    scores["scores"] = {"hp": 4}
    assert not holds(scores, ctx(state, this=pig))
    # ValueCheckCondition: a score number provider (ScoreboardValue, fixed holder) in a range
    state.scoreboard.set("#n", "hp", 7)
    check = {"condition": "value_check", "value": {"type": "score", "target": {"type": "fixed", "name": "#n"},
                                                    "score": "hp"}, "range": {"min": 7}}
    assert holds(check, ctx(state))


def test_int_range_bounds_are_read_with_get_int(state):
    # IntRange (entity_scores, value_check, time_check): its bounds are number providers compared
    # through NumberProvider.getInt = Math.round(getFloat), so a bound written 1.2 is 1 and 1.5 is 2
    # (IntRange's predicate); MinMaxBounds (an entity's level, an item's count) keep what is written
    pig = state.entities.summon("minecraft:pig", (0.0, 0.0, 0.0))
    state.scoreboard.add_objective("hp")
    state.scoreboard.set(pig.score_holder, "hp", 1)
    at_least = {"condition": "entity_scores", "entity": "this", "scores": {"hp": {"min": 1.2}}}
    assert holds(at_least, ctx(state, this=pig))
    at_least["scores"]["hp"]["min"] = 1.5
    assert not holds(at_least, ctx(state, this=pig))
    state.daytime = 1
    assert holds({"condition": "time_check", "value": {"max": 0.7}}, ctx(state))
    assert not in_range({"min": 1.2}, 1)


def test_min_max_bounds_ints_read_their_bounds_with_codec_int(state):
    # MinMaxBounds.Ints.CODEC = createCodec(Codec.INT, ...): JsonOps.getNumberValue hands Gson's
    # LazilyParsedNumber to Number.intValue, which truncates a decimal toward zero (BigDecimal.intValue)
    # and keeps the low 32 bits of a number past an int; a boolean is 1 or 0. MinMaxBounds.Doubles
    # (distance, position, damage) keep the number written.
    assert in_ints({"min": 1.9}, 1) and not in_ints({"min": 2.1}, 1)
    assert in_ints({"max": -1.9}, -1) and not in_ints({"max": -1.9}, 0)
    assert in_ints(2.7, 2) and not in_ints(2.7, 3)
    assert in_ints({"min": True, "max": True}, 1)
    assert in_ints(2**32 + 5, 5)  # (int) Long.parseLong
    assert not in_range({"min": 1.9}, 1) and in_range({"max": 1.9}, 1.5)
    slime = state.entities.summon("minecraft:slime", (0.0, 0.0, 0.0))
    slime.data["Size"] = Int(1)  # SlimePredicate: Size + 1 = 2
    size = {"condition": "entity_properties", "entity": "this",
            "predicate": {"type_specific": {"type": "slime", "size": {"min": 2.99, "max": 2.01}}}}
    assert holds(size, ctx(state, this=slime))
    size["predicate"]["type_specific"]["size"] = {"min": 3.0}
    assert not holds(size, ctx(state, this=slime))


def test_time_check_uses_day_time_modulo_period(state):
    # TimeCheck.test: level.getDayTime(), % period when given
    state.daytime = 24000 * 3 + 14000
    assert holds({"condition": "time_check", "value": {"min": 13000}, "period": 24000}, ctx(state))
    assert not holds({"condition": "time_check", "value": {"max": 23000}}, ctx(state))


def test_random_chance_draws_from_the_level_random(state):
    # LootItemRandomChanceCondition: random.nextFloat() < chance
    hits = sum(holds({"condition": "random_chance", "chance": 0.25}, ctx(state)) for _ in range(4000))
    assert 850 < hits < 1150
    assert not holds({"condition": "random_chance", "chance": 0.0}, ctx(state))


def test_location_check_block_state_and_fluid(state):
    # LocationCheck: origin + offset; LocationPredicate: the block at BlockPos.containing(pos)
    state.blocks.setblock((0, 1, 0), BlockSpec("minecraft:oak_stairs", False, (("facing", "east"),), None))
    state.blocks.setblock((0, 0, 0), BlockSpec("minecraft:water", False, (("level", "0"),), None))
    stairs = {"condition": "location_check", "offsetY": 1,
              "predicate": {"block": {"blocks": "minecraft:oak_stairs", "state": {"facing": "east"}}}}
    assert holds(stairs, ctx(state, origin=(0.5, 0.2, 0.5)))
    assert not holds(stairs, ctx(state, origin=(1.5, 0.2, 0.5)))
    water = {"condition": "location_check", "predicate": {"fluid": {"fluids": "minecraft:water"}}}
    assert holds(water, ctx(state, origin=(0.5, 0.9, 0.5)))
    assert not holds(water, ctx(state, origin=(0.5, 1.9, 0.5)))
    # a state the block was placed without, in a release after the newest registries (26.1): its
    # default is not known here, said so
    state.version = (26, 2, 0)
    with pytest.raises(Unmodelled, match="half"):
        holds({"condition": "location_check", "offsetY": 1,
              "predicate": {"block": {"state": {"half": "bottom"}}}}, ctx(state, origin=(0.5, 0.2, 0.5)))


def test_a_state_property_the_block_lacks_fails_where_the_release_has_registries():
    # PropertyMatcher.match: a property the block's StateDefinition does not have is false; placed
    # blocks hold their whole default state (BlockStateParser), so a property not listed is one the
    # block lacks in a release dpemu has registries of, and unknown in a later one
    exact = WorldState(version=(1, 21, 11))
    exact.blocks.setblock((0, 0, 0), with_defaults(parse_block("oak_stairs"), exact.version))
    facing = {"condition": "location_check", "predicate": {"block": {"state": {"facing": "north", "half": "bottom"}}}}
    powered = {"condition": "location_check", "predicate": {"block": {"state": {"powered": "true"}}}}
    assert holds(facing, ctx(exact, origin=(0.5, 0.5, 0.5)))
    assert not holds(powered, ctx(exact, origin=(0.5, 0.5, 0.5)))
    later = WorldState(version=(26, 2, 0))
    later.blocks.setblock((0, 0, 0), with_defaults(parse_block("oak_stairs"), later.version))
    assert holds(facing, ctx(later, origin=(0.5, 0.5, 0.5)))
    with pytest.raises(Unmodelled, match="'powered' state of minecraft:oak_stairs"):
        holds(powered, ctx(later, origin=(0.5, 0.5, 0.5)))


def test_match_tool_reads_the_enchantments_sub_predicate(state):
    # ItemPredicate.predicates: ItemSubPredicates.ENCHANTMENTS / STORED_ENCHANTMENTS
    # (ItemEnchantmentsPredicate over the stack's component)
    book = ItemStack("minecraft:enchanted_book", 1, Compound({"minecraft:stored_enchantments": Compound(
        levels=Compound({"minecraft:mending": Int(1)}))}))
    stored = {"condition": "match_tool", "predicate": {"predicates": {
        "minecraft:stored_enchantments": [{"enchantments": "minecraft:mending", "levels": 1}]}}}
    assert holds(stored, ctx(state, tool=book))
    enchanted = {"condition": "match_tool", "predicate": {"predicates": {"minecraft:enchantments": [{}]}}}
    assert not holds(enchanted, ctx(state, tool=book))


def test_command_parameter_set_lacks_tool_block_and_damage(state):
    # ExecuteCommand.checkCustomPredicate uses LootContextParamSets.COMMAND: origin and this only
    assert not holds({"condition": "match_tool"}, ctx(state))
    assert not holds({"condition": "block_state_property", "block": "minecraft:stone"}, ctx(state))
    assert not holds({"condition": "killed_by_player"}, ctx(state))
    assert holds({"condition": "survives_explosion"}, ctx(state))  # ExplosionCondition: no radius -> true
    assert not holds({"condition": "damage_source_properties"}, ctx(state))


def test_match_tool_item_predicate(state):
    # MatchTool + ItemPredicate: items, count, components (exact), predicates.custom_data (partial)
    stack = ItemStack("minecraft:stick", 3, Compound({"minecraft:custom_data": Compound(magic=Byte(1), more=Int(2))}))
    tool = ctx(state, tool=stack)
    assert holds({"condition": "match_tool", "predicate": {"items": "minecraft:stick", "count": {"min": 2}}}, tool)
    assert not holds({"condition": "match_tool", "predicate": {"items": ["minecraft:stone"]}}, tool)
    assert holds({"condition": "match_tool", "predicate": {"predicates": {"custom_data": "{magic:1b}"}}}, tool)
    assert not holds({"condition": "match_tool", "predicate": {"predicates": {"custom_data": "{magic:0b}"}}}, tool)


def test_flags_effects_and_unmodelled_fields(state):
    # EntityFlagsPredicate / MobEffectsPredicate (active_effects as the entity saves them)
    player = state.entities.add_player("Alex", (0.0, 0.0, 0.0))
    player.sneaking = True
    player.data["active_effects"] = List([Compound(id=String("minecraft:speed"), amplifier=Byte(1),
                                                   duration=Int(100))])
    this = ctx(state, this=player)
    props = lambda p: {"condition": "entity_properties", "entity": "this", "predicate": p}  # noqa: E731
    assert holds(props({"flags": {"is_sneaking": True}}), this)
    assert not holds(props({"flags": {"is_sprinting": True}}), this)
    assert holds(props({"effects": {"minecraft:speed": {"amplifier": {"min": 1}}}}), this)
    assert not holds(props({"effects": {"minecraft:slowness": {}}}), this)
    assert holds(props({"type_specific": {"type": "player", "gamemode": ["survival"]}}), this)
    # EntityPredicate.targetedEntity: only a Mob has a target (getTarget); a mob without AI never
    # gets one; another mob's target is its AI's, not modelled
    assert not holds(props({"targeted_entity": {}}), this)
    zombie = state.entities.summon("minecraft:zombie", (0.0, 0.0, 0.0))
    calm = state.entities.summon("minecraft:zombie", (0.0, 0.0, 0.0), Compound(NoAI=Byte(1)))
    assert not holds(props({"targeted_entity": {}}), ctx(state, this=calm))
    with pytest.raises(Unmodelled, match="targeted_entity"):
        holds(props({"targeted_entity": {}}), ctx(state, this=zombie))
    with pytest.raises(Unmodelled, match="'minecraft:nope'"):
        holds({"condition": "minecraft:nope"}, this)


def test_entity_flags_swimming_flying_water(state):
    # EntityFlagsPredicate.matches (decompiled 26.1.2): is_in_water reads Entity.isInWater, is_swimming
    # the flag Entity.updateSwimming sets (never without sprinting in water), is_flying a player's
    # abilities (GameType.updatePlayerAbilities: a spectator flies, creative keeps it), is_baby and
    # is_fall_flying only test living entities; a flag the release's codec lacks is ignored
    state.version = (1, 21, 11)
    props = lambda p: {"condition": "entity_properties", "entity": "this", "predicate": {"flags": p}}  # noqa: E731
    player = state.entities.add_player("Alex", (0.5, 0.0, 0.5))
    this = ctx(state, this=player)
    assert holds(props({"is_swimming": False, "is_flying": False, "is_in_water": False}), this)
    state.blocks.place((0, 0, 0), with_defaults(parse_block("minecraft:water"), state.version))
    assert holds(props({"is_in_water": True, "is_swimming": False}), this)
    player.sprinting = True
    with pytest.raises(Unmodelled, match="sprinting in water"):
        holds(props({"is_swimming": True}), this)
    player.gamemode, player.flying = "spectator", True
    assert holds(props({"is_flying": True}), this)
    marker = state.entities.summon("minecraft:marker", (9.0, 0.0, 9.0))
    assert holds(props({"is_baby": True, "is_fall_flying": True}), ctx(state, this=marker))  # not living: skipped
    state.version = (1, 21, 4)  # is_in_water is not a field before 1.21.11: ignored
    assert holds(props({"is_in_water": False}), this)


def test_gamemode_sets_the_abilities_flying_flag():
    from emulator.world.entity_flags import flying_after
    assert flying_after("spectator", False) and flying_after("creative", True)
    assert not flying_after("creative", False) and not flying_after("survival", True)


def test_inline_predicates_read_snbt():
    # 1.20.5+ inline predicates: SNBT read through the condition codec
    value = parse_inline('{condition:"minecraft:random_chance",chance:0.5f}')
    assert value == {"condition": "minecraft:random_chance", "chance": pytest.approx(0.5)}


# ---------------------------------------------------------------------- one evaluator for loot and predicates
def props(predicate, entity="this"):
    return {"condition": "entity_properties", "entity": entity, "predicate": predicate}


def test_loot_pools_read_the_same_conditions_as_predicates(state):
    # LootPool.addRandomItems: the pool's conditions are LootItemConditions, the same codec and test
    # as a predicate file's (an entity_properties gate on the looted entity)
    table = {"pools": [{"rolls": 1, "conditions": [props({"type": "minecraft:pig"})],
                        "entries": [{"type": "item", "name": "porkchop"}]}]}
    pig = state.entities.summon("minecraft:pig", (0.0, 0.0, 0.0))
    cow = state.entities.summon("minecraft:cow", (0.0, 0.0, 0.0))
    assert [s.id for s in loot.roll_table(table, ctx(state, this=pig))] == ["minecraft:porkchop"]
    assert loot.roll_table(table, ctx(state, this=cow)) == []


def test_value_check_reads_the_provider_as_an_int(state):
    # ValueCheckCondition.test: range.test(ctx, provider.getInt(ctx)); getInt rounds (Mth.floor(f + 0.5))
    assert holds({"condition": "value_check", "value": 2.6, "range": {"min": 3, "max": 3}}, ctx(state))
    assert not holds({"condition": "value_check", "value": 2.4, "range": {"min": 3}}, ctx(state))


def test_kill_loot_parameters(state):
    # LootCommand.dropKillLoot: the killer is attacker and direct attacker, the attacking player when
    # it is one (LootItemKilledByPlayerCondition); the damage source is magic, with no entity
    player = state.entities.add_player("Alex", (0.0, 0.0, 0.0))
    zombie = state.entities.summon("minecraft:zombie", (0.0, 0.0, 0.0))
    by_player = ctx(state, this=zombie, damage_source=DamageSource("minecraft:magic")).killed_by(player)
    assert holds({"condition": "killed_by_player"}, by_player)
    assert holds(props({"type": "minecraft:player"}, "attacker"), by_player)
    assert not holds({"condition": "killed_by_player"}, ctx(state, this=player).killed_by(zombie))
    assert holds({"condition": "damage_source_properties", "predicate": {}}, by_player)
    assert not holds({"condition": "damage_source_properties", "predicate": {"source_entity": {}}}, by_player)


def test_damage_source_properties(state):
    # DamageSourceCondition.test: needs the damage source and the origin; DamageSourcePredicate:
    # each tag {id, expected}, direct_entity and source_entity (EntityPredicate.matches from the
    # origin; an absent entity fails), is_direct (DamageSource.isDirect: causing == direct entity,
    # so a source with neither is direct)
    state.resources = Resources(tags={"damage_type": {"t:arcane": RegistryTag(frozenset({"minecraft:magic"}))}})
    player = state.entities.add_player("Alex", (3.0, 0.0, 0.0))
    arrow = state.entities.summon("minecraft:arrow", (1.0, 0.0, 0.0))
    shot = ctx(state, damage_source=DamageSource("minecraft:arrow", player, arrow))
    magic = ctx(state, damage_source=DamageSource("minecraft:magic"))

    def source(predicate, context):
        return holds({"condition": "damage_source_properties", "predicate": predicate}, context)

    assert source({"source_entity": {"type": "minecraft:player", "distance": {"absolute": {"min": 2.5}}},
                   "direct_entity": {"type": "minecraft:arrow"}, "is_direct": False}, shot)
    assert not source({"source_entity": {"distance": {"absolute": {"max": 2.5}}}}, shot)
    assert not source({"is_direct": True}, shot) and source({"is_direct": True}, magic)
    assert source({"tags": [{"id": "t:arcane", "expected": True}]}, magic)
    assert source({"tags": [{"id": "t:arcane", "expected": False}]}, shot)
    assert not source({"tags": [{"id": "t:arcane", "expected": True}]}, shot)
    assert not holds({"condition": "damage_source_properties"}, ctx(state))  # no damage source
    assert not holds({"condition": "damage_source_properties"}, LootContext(state, None, damage_source=magic.damage_source))
    with pytest.raises(Unmodelled, match="is_fire"):  # the pre-1.19.4 flags are not modelled
        source({"is_fire": True}, magic)


def test_enchanted_bonus_without_an_enchanted_attacker_is_the_unenchanted_chance(state):
    # LootItemRandomChanceWithEnchantedBonusCondition: level 0 (no attacker, or none of the
    # enchantment on its equipment) takes unenchanted_chance; a level above 0 is not modelled
    condition = {"condition": "random_chance_with_enchanted_bonus", "enchantment": "minecraft:looting",
                 "unenchanted_chance": 1.0, "enchanted_chance": 0.0}
    zombie = state.entities.summon("minecraft:zombie", (0.0, 0.0, 0.0))
    assert holds(condition, ctx(state).killed_by(zombie))
    sword = ItemStack("minecraft:iron_sword", 1, Compound({"minecraft:enchantments": Compound(
        levels=Compound({"minecraft:looting": Int(2)}))}))
    inventories.entity_slot(zombie, inventories.MAINHAND, state.version).set(sword)
    with pytest.raises(Unmodelled, match="enchantment level"):
        holds(condition, ctx(state).killed_by(zombie))


# ---------------------------------------------------------------------- equipment
@pytest.mark.parametrize("version", [(1, 21, 4), (1, 21, 5)])
def test_equipment_reads_each_slot_of_a_living_entity(version):
    # EntityEquipmentPredicate.matches: a LivingEntity; each given slot's ItemPredicate.test on
    # getItemBySlot (an empty slot is the empty stack: `{}` matches it, a count of at least 1 not);
    # saved as HandItems/ArmorItems before 1.21.5 and as the equipment compound from it
    state = WorldState(version=version)
    zombie = state.entities.summon("minecraft:zombie", (0.0, 0.0, 0.0))
    inventories.entity_slot(zombie, inventories.ARMOR_SLOTS["head"], version).set(ItemStack("minecraft:iron_helmet"))
    inventories.entity_slot(zombie, inventories.MAINHAND, version).set(ItemStack("minecraft:stick", 5))
    this = ctx(state, this=zombie)
    assert holds(props({"equipment": {"head": {"items": "minecraft:iron_helmet"}}}), this)
    assert not holds(props({"equipment": {"head": {"items": ["minecraft:diamond_helmet"]}}}), this)
    assert holds(props({"equipment": {"mainhand": {"items": "minecraft:stick", "count": {"min": 5}}}}), this)
    assert not holds(props({"equipment": {"mainhand": {"count": 6}}}), this)
    assert holds(props({"equipment": {"feet": {}, "offhand": {}}}), this)  # empty slots
    assert not holds(props({"equipment": {"feet": {"count": {"min": 1}}}}), this)
    # the iron helmet's default max_damage is one of its components (DataComponentPredicate)
    assert holds(props({"equipment": {"head": {"components": {"minecraft:max_damage": 165}}}}), this)
    marker = state.entities.summon("minecraft:marker", (0.0, 0.0, 0.0))
    assert not holds(props({"equipment": {}}), ctx(state, this=marker))  # not a LivingEntity


def test_a_players_mainhand_is_its_selected_slot(state):
    # Player.getItemBySlot(MAINHAND): Inventory.getSelected, the hotbar slot SelectedItemSlot names
    player = state.entities.add_player("Alex", (0.0, 0.0, 0.0))
    inventories.entity_slot(player, 2, state.version).set(ItemStack("minecraft:carrot_on_a_stick"))
    held = props({"equipment": {"mainhand": {"items": "minecraft:carrot_on_a_stick"}}})
    assert not holds(held, ctx(state, this=player))
    player.data["SelectedItemSlot"] = Int(2)
    assert holds(held, ctx(state, this=player))
    assert holds(props({"equipment": {"body": {}}}), ctx(state, this=player))  # a player's body slot is empty


def test_slots_need_one_matching_slot_in_each_range(state):
    # SlotsPredicate.matches: for each SlotRange, some Entity.getSlot(id) stack the ItemPredicate accepts
    player = state.entities.add_player("Alex", (0.0, 0.0, 0.0))
    inventories.entity_slot(player, 20, state.version).set(ItemStack("minecraft:diamond", 3))
    this = ctx(state, this=player)
    assert holds(props({"slots": {"inventory.*": {"items": "minecraft:diamond", "count": 3}}}), this)
    assert not holds(props({"slots": {"hotbar.*": {"items": "minecraft:diamond"}}}), this)
    assert holds(props({"slots": {"container.*": {"items": "minecraft:diamond"}, "armor.head": {}}}), this)
    marker = state.entities.summon("minecraft:marker", (0.0, 0.0, 0.0))
    assert not holds(props({"slots": {"weapon.mainhand": {"count": {"min": 1}}}}), ctx(state, this=marker))


@pytest.mark.parametrize("version,matches", [((1, 20, 5), True), ((1, 21, 10), True), ((1, 21, 11), False),
                                             ((26, 1, 0), False)])
def test_a_slot_the_entity_lacks_is_the_empty_stack_until_1_21_11(version, matches):
    # SlotsPredicate.matchSlots: before 1.21.11 Entity.getSlot gives SlotAccess.NULL for a slot the
    # entity does not have, whose get() is ItemStack.EMPTY, so a predicate the empty stack passes
    # (`{}`, `minecraft:air`) matches it; from 1.21.11 it reads the entity as a SlotProvider whose
    # getSlot is null there, and the slot is skipped (mappings history: matches(SlotProvider))
    state = WorldState(version=version)
    marker = state.entities.summon("minecraft:marker", (0.0, 0.0, 0.0))
    this = ctx(state, this=marker)
    assert holds(props({"slots": {"weapon.mainhand": {}}}), this) == matches
    assert holds(props({"slots": {"container.*": {"items": "minecraft:air"}}}), this) == matches
    zombie = state.entities.summon("minecraft:zombie", (0.0, 0.0, 0.0))  # its hands are slots it has
    assert holds(props({"slots": {"weapon.mainhand": {}}}), ctx(state, this=zombie))


@pytest.mark.parametrize("version", [(1, 16, 5), (1, 20, 4)])
def test_item_predicate_fields_before_1_20_5(version):
    # ItemPredicate.matches before 1.20.5: durability (max damage - Damage of a damageable item),
    # enchantments / stored_enchantments (EnchantmentPredicate.containedIn the deserialized tag
    # list; with neither enchantment nor levels it is true), potion (the tag's Potion)
    state = WorldState(version=version)
    pick = ItemStack("minecraft:diamond_pickaxe", 1, tag=Compound(Damage=Int(61), Enchantments=List([
        Compound(id=String("minecraft:silk_touch"), lvl=Int(1))])))
    tool = ctx(state, tool=pick)

    def tool_is(**fields):
        return holds({"condition": "match_tool", "predicate": fields}, tool)
    assert tool_is(durability={"max": 1500}) and not tool_is(durability={"min": 1501})
    assert tool_is(enchantments=[{"enchantment": "minecraft:silk_touch", "levels": {"min": 1}}])
    assert not tool_is(enchantments=[{"enchantment": "minecraft:fortune"}])
    assert tool_is(enchantments=[{"levels": 1}]) and not tool_is(enchantments=[{"levels": {"min": 2}}])
    assert tool_is(stored_enchantments=[{}]) and not tool_is(stored_enchantments=[{"levels": 1}])
    assert tool_is(potion="minecraft:empty") and not tool_is(potion="minecraft:swiftness")


def test_the_old_item_predicate_fields_are_ignored_from_1_20_5(state):
    # ItemPredicate.CODEC from 1.20.5 has items, count, components, predicates: other keys are ignored
    assert holds({"condition": "match_tool", "predicate": {"durability": {"min": 9999}}},
                 ctx(state, tool=ItemStack("minecraft:stick")))


@pytest.mark.parametrize("field,value,reason", [
    ("biomes", "minecraft:plains", "generator"), ("structures", "#minecraft:village", "structures of this world"),
    ("light", {"light": {"min": 1}}, "'light' .*sky light of t:void"), ("can_see_sky", True, "sky light of t:void"),
])
def test_location_fields_the_world_does_not_keep_are_reported(state, field, value, reason):
    # LocationPredicate.matches: biomes, structures, light and can_see_sky read what the
    # emulator's world does not keep (no terrain, no light): not modelled, never a silent yes or no;
    # a field the world keeps that fails first makes the predicate false all the same
    check = {"condition": "location_check", "predicate": {field: value}}
    with pytest.raises(Unmodelled, match=reason):
        holds(check, ctx(state, dimension="t:void"))
    check["predicate"]["block"] = {"blocks": "minecraft:stone"}
    assert not holds(check, ctx(state))


def test_the_test_servers_world_has_no_structures(state):
    # GameTestServer.WORLD_OPTIONS = new WorldOptions(0L, false, false): no structure is generated, so
    # LocationPredicate.matches' getStructureWithPieceAt is never valid and a structures field fails
    state.structures_generated = False
    for field, value in (("structures", "#minecraft:village"), ("structures", []), ("structure", "minecraft:fortress")):
        assert not holds({"condition": "location_check", "predicate": {field: value}}, ctx(state))


def test_smokey_looks_down_for_a_lit_campfire(state):
    # CampfireBlock.isSmokeyPos: up to 5 blocks down a lit #campfires block makes the position smokey;
    # the first block whose collision shape meets VIRTUAL_FENCE_POST ends the search, smokey only
    # when a lit campfire is right under it (a campfire's own SHAPE meets the post)
    smokey = lambda pos: holds({"condition": "location_check", "predicate": {"smokey": True}},  # noqa: E731
                               ctx(state, origin=pos))
    place = lambda pos, block: state.blocks.place(pos, with_defaults(parse_block(block), state.version))  # noqa: E731
    place((0, 0, 0), "minecraft:campfire[lit=true]")
    assert smokey((0.5, 5.5, 0.5)) and not smokey((0.5, 6.5, 0.5)) and not smokey((0.5, 0.5, 0.5))
    assert holds({"condition": "location_check", "predicate": {"smokey": False}}, ctx(state, origin=(0.5, 6.5, 0.5)))
    place((0, 1, 0), "minecraft:oak_planks")  # a full cube right over the fire: its smoke still shows above
    assert smokey((0.5, 4.5, 0.5))
    place((0, 2, 0), "minecraft:stone")  # two blocks over it: the stone ends the search
    assert not smokey((0.5, 4.5, 0.5)) and not smokey((0.5, 3.5, 0.5))
    place((0, 10, 0), "minecraft:soul_campfire[lit=false]")
    place((0, 9, 0), "minecraft:soul_campfire[lit=true]")  # an unlit one over a lit one passes its smoke
    assert smokey((0.5, 12.5, 0.5))
    place((0, 11, 0), "minecraft:oak_fence")  # a shape the emulator does not keep
    with pytest.raises(Unmodelled, match="shape of minecraft:oak_fence"):
        smokey((0.5, 12.5, 0.5))


def test_can_see_sky_is_sky_light_15_straight_down(state):
    # BlockAndTintGetter.canSeeSky: sky light 15, which only passes straight down through blocks
    # that do not dampen it (getLightBlock 0: glass, barriers, torches ...) nor occlude it with a
    # face (a bottom slab lets it in from above, not out below); the nether has no sky light
    sees = lambda pos, **kw: holds({"condition": "location_check", "predicate": {"can_see_sky": True}},  # noqa: E731
                                   ctx(state, origin=pos, **kw))
    place = lambda pos, block: state.blocks.place(pos, with_defaults(parse_block(block), state.version))  # noqa: E731
    assert sees((0.5, 64.0, 0.5)) and not sees((0.5, 64.0, 0.5), dimension="minecraft:the_nether")
    place((0, 70, 0), "minecraft:glass")
    place((0, 80, 0), "minecraft:barrier")
    place((0, 65, 0), "minecraft:torch")
    assert sees((0.5, 64.0, 0.5)) and sees((0.5, 70.5, 0.5))
    place((0, 64, 0), "minecraft:stone_slab[type=bottom]")
    assert sees((0.5, 64.2, 0.5)) and not sees((0.5, 63.0, 0.5))
    place((0, 64, 0), "minecraft:oak_leaves")  # dampens sky light by 1: 14 below
    assert not sees((0.5, 60.0, 0.5)) and not sees((0.5, 64.5, 0.5))
    place((0, 64, 0), "minecraft:air")
    place((0, 90, 0), "minecraft:oak_fence")  # a shape whose light occlusion is not kept here
    with pytest.raises(Unmodelled, match="oak_fence"):
        sees((0.5, 60.0, 0.5))
    place((0, 95, 0), "minecraft:stone")  # a full cube above decides it
    assert not sees((0.5, 60.0, 0.5))


def test_light_is_the_sky_less_its_darkening_where_nothing_gives_light(state):
    # LightPredicate: Level.getMaxLocalRawBrightness = max(block light, sky light - skyDarken);
    # skyDarken = (int)((1 - d2) * 11), d2 from Mth.cos of the time of day (Level.updateSkyBrightness)
    from emulator.world.light import sky_darken
    level = lambda bounds, pos=(0.5, 64.0, 0.5), **kw: holds(  # noqa: E731
        {"condition": "location_check", "predicate": {"light": {"light": bounds}}}, ctx(state, origin=pos, **kw))
    assert [sky_darken(t) for t in (0, 6000, 12000, 13000, 18000, 23500)] == [0, 0, 0, 6, 11, 3]
    state.sky_darken = sky_darken(18000)
    assert level(4) and not level({"min": 5})  # midnight under the open sky: 15 - 11
    assert level(0, dimension="minecraft:the_nether")  # no sky light, nothing lit
    state.blocks.place((3, 64, 0), with_defaults(parse_block("minecraft:torch"), state.version))
    assert level(11) and level(4, pos=(20.5, 64.0, 0.5))  # the torch's 14 less 3 steps; 20 steps away: none


def _light(state, pos, **kw) -> int:
    """The light a location predicate reads at ``pos``: the one level its ``light`` range takes."""
    found = [n for n in range(16) if holds({"condition": "location_check", "predicate": {"light": {"light": n}}},
                                          ctx(state, origin=pos, **kw))]
    assert len(found) == 1
    return found[0]


def test_block_light_is_each_states_emission_spread_one_less_a_step(state):
    # BlockLightEngine.propagateIncrease: a neighbour gets the level less LightEngine.getOpacity
    # (max(1, getLightBlock)); the emission is BlockStateBase.getLightEmission (Blocks.java lightLevel:
    # litBlockEmission, CandleBlock.LIGHT_EMISSION, LightBlock.LIGHT_EMISSION, RespawnAnchorBlock)
    state.sky_darken = 15  # no sky light left: the block light alone
    place = lambda pos, block: state.blocks.place(pos, with_defaults(parse_block(block), state.version))  # noqa: E731
    for block, level in (("minecraft:torch", 14), ("minecraft:glowstone", 15), ("minecraft:furnace[lit=true]", 13),
                         ("minecraft:furnace", 0), ("minecraft:candle[candles=3,lit=true]", 9),
                         ("minecraft:candle[candles=3]", 0), ("minecraft:light[level=6]", 6),
                         ("minecraft:respawn_anchor[charges=2]", 7), ("minecraft:soul_torch", 10)):
        place((0, 64, 0), block)
        assert _light(state, (0.5, 64.0, 0.5)) == level and _light(state, (2.5, 64.0, 1.5)) == max(0, level - 3)
        place((0, 64, 0), "minecraft:air")
    # emissions read from a state property (VaultState.LightLevel, TrialSpawnerState) and a constant one;
    # these blocks' shapes are not known here, so only what they give is checked
    for block, level in (("minecraft:lava_cauldron", 15), ("minecraft:vault", 6),
                         ("minecraft:vault[vault_state=active]", 12), ("minecraft:trial_spawner", 0),
                         ("minecraft:trial_spawner[trial_spawner_state=active]", 8)):
        assert emission(with_defaults(parse_block(block), state.version).state) == level, block
    for stem in ("pumpkin_stem", "attached_melon_stem", "big_dripleaf_stem"):  # plants without collision, not logs
        assert light_block(with_defaults(parse_block("minecraft:" + stem), state.version).state) == 0, stem
    place((0, 64, 0), "minecraft:torch")
    place((1, 64, 0), "minecraft:glass")  # getLightBlock 0 (propagatesSkylightDown): one a step still
    assert _light(state, (2.5, 64.0, 0.5)) == 12
    place((1, 64, 0), "minecraft:oak_leaves")  # not solid render, not propagatesSkylightDown: 1
    assert _light(state, (2.5, 64.0, 0.5)) == 12 and _light(state, (1.5, 64.0, 0.5)) == 13
    place((1, 64, 0), "minecraft:stone")  # 15: none passes, the light goes round it
    assert _light(state, (1.5, 64.0, 0.5)) == 0 and _light(state, (2.5, 64.0, 0.5)) == 10
    place((1, 64, 0), "minecraft:water")  # a fluid dampens by 1
    assert _light(state, (2.5, 64.0, 0.5)) == 12
    place((1, 64, 0), "minecraft:stone_slab[type=bottom]")  # its faces occlude light one way only
    with pytest.raises(Unmodelled, match="stone_slab"):
        _light(state, (2.5, 64.0, 0.5))


def test_sky_light_reaches_under_a_roof_sideways_and_changes_with_the_blocks(state):
    # SkyLightEngine: 15 straight down where the sky is seen, then one less a step down and sideways;
    # the predicate reads max(block light, sky light - skyDarken) (LevelReader.getMaxLocalRawBrightness)
    def fill(block, y, r):
        for x in range(-r, r + 1):
            for z in range(-r, r + 1):
                state.blocks.place((x, y, z), with_defaults(parse_block(block), state.version))
    assert _light(state, (0.5, 64.0, 0.5)) == 15
    fill("minecraft:stone", 65, 0)  # one block over: the columns beside it see the sky
    assert _light(state, (0.5, 64.0, 0.5)) == 14 and _light(state, (0.5, 60.0, 0.5)) == 14
    fill("minecraft:stone", 65, 3)  # a 7 x 7 roof: 4 steps to the nearest open column
    assert _light(state, (0.5, 64.0, 0.5)) == 11 and _light(state, (0.5, 63.0, 0.5)) == 11
    state.sky_darken = 11
    assert _light(state, (0.5, 64.0, 0.5)) == 0 and _light(state, (3.5, 64.0, 0.5)) == 3
    state.blocks.place((0, 66, 0), with_defaults(parse_block("minecraft:glowstone"), state.version))  # on the roof
    assert _light(state, (0.5, 67.0, 0.5)) == 14  # under the roof only round its edge: 10 steps
    assert _light(state, (0.5, 64.0, 0.5)) == 5
    fill("minecraft:air", 65, 3)  # the roof gone: the light follows the blocks as they are now
    assert _light(state, (0.5, 64.0, 0.5)) == 13  # glowstone 2 steps above (15 - 2) beats 15 - 11
    assert _light(state, (0.5, 64.0, 0.5), dimension="minecraft:the_nether") == 0


def test_the_player_predicate_reads_the_recipe_book(state):
    # PlayerPredicate.matches: each recipe's presence in the player's RecipeBook equals its boolean
    state.resources = Resources(recipes={"t:wand": "minecraft:crafting_shapeless"})
    player = state.entities.add_player("Alex", (0.0, 0.0, 0.0))
    recipes.award(player, ["t:wand"], state.resources, lambda recipe_id: None)
    check = lambda wanted: holds({"condition": "entity_properties", "entity": "this", "predicate": {  # noqa: E731
        "type_specific": {"type": "player", "recipes": wanted}}}, ctx(state, this=player))
    assert check({"t:wand": True, "t:staff": False}) and not check({"t:wand": False}) and not check({"t:staff": True})


def test_stepping_on_reads_the_centre_of_the_block_below(state):
    # EntityPredicate.matches: location at the entity's exact position; stepping_on at
    # Vec3.atCenterOf(getOnPos()), the block 0.2 below the feet; movement_affected_by 0.500001 below
    state.version = (1, 21, 0)
    state.blocks.setblock((0, 63, 0), BlockSpec("minecraft:stone", False, (), None))
    pig = state.entities.summon("minecraft:pig", (0.3, 64.0, 0.7))
    near = lambda field, x: holds({"condition": "entity_properties", "entity": "this", "predicate": {  # noqa: E731
        field: {"position": {"x": {"min": x - 0.01, "max": x + 0.01}}, "block": {"blocks": "minecraft:stone"}}}},
        ctx(state, this=pig))
    assert near("stepping_on", 0.5) and near("movement_affected_by", 0.5) and not near("stepping_on", 0.3)
    assert not near("location", 0.3)  # its own block is air
    # from 1.21.11 stepping_on also needs the entity on the ground (EntityPredicate.matches: onGround)
    state.version = (1, 21, 11)
    assert not near("stepping_on", 0.5) and near("movement_affected_by", 0.5)
    pig.data["OnGround"] = Byte(1)
    assert near("stepping_on", 0.5)
    assert holds({"condition": "entity_properties", "entity": "this", "predicate": {
        "location": {"position": {"x": {"min": 0.29, "max": 0.31}}}}}, ctx(state, this=pig))


def test_entity_components_compare_what_the_entity_saves():
    # EntityPredicate.matches: components.test(entity) (1.21.5+), each listed component equal to
    # Entity.get's: Cat.get (cat/variant from ``variant``, cat/collar from CollarColor, red when
    # absent: DEFAULT_COLLAR_COLOR), Sheep.get (sheep/color from Color, DyeColor's legacy ids),
    # Fox.get (fox/variant from Type), Villager.get (villager/variant: VillagerData.type)
    state = WorldState(version=(1, 21, 5))
    props = lambda c: {"condition": "entity_properties", "entity": "this", "predicate": {"components": c}}  # noqa: E731
    cat = state.entities.summon("minecraft:cat", (0.0, 0.0, 0.0), Compound(variant=String("minecraft:black")))
    this = ctx(state, this=cat)
    assert holds(props({"minecraft:cat/variant": "black"}), this)
    assert holds(props({"cat/variant": "minecraft:black", "cat/collar": "red"}), this)
    assert not holds(props({"cat/variant": "minecraft:tabby"}), this)
    assert not holds(props({"wolf/variant": "minecraft:pale"}), this)  # a cat has no wolf variant
    sheep = state.entities.summon("minecraft:sheep", (0.0, 0.0, 0.0), Compound(Color=Byte(14)))
    assert holds(props({"sheep/color": "red"}), ctx(state, this=sheep))
    fox = state.entities.summon("minecraft:fox", (0.0, 0.0, 0.0), Compound(Type=String("snow")))
    assert holds(props({"fox/variant": "snow"}), ctx(state, this=fox))
    villager = state.entities.summon("minecraft:villager", (0.0, 0.0, 0.0), Compound(VillagerData=Compound(
        type=String("minecraft:desert"), profession=String("minecraft:none"), level=Int(1))))
    assert holds(props({"villager/variant": "desert"}), ctx(state, this=villager))
    # a variant the spawn picked (summoned without it: Mob.finalizeSpawn), or a component the
    # emulator does not read, is not modelled
    stray = state.entities.summon("minecraft:cat", (0.0, 0.0, 0.0))
    with pytest.raises(Unmodelled, match="finalizeSpawn"):
        holds(props({"cat/variant": "black"}), ctx(state, this=stray))
    with pytest.raises(Unmodelled, match="custom_data"):
        holds(props({"custom_data": {"a": 1}}), this)
    # before 1.21.5 the entity predicate has no components field: ignored
    assert holds(props({"cat/variant": "minecraft:tabby"}), ctx(WorldState(version=(1, 21, 4)), this=cat))


def test_the_custom_name_component_compares_components_as_the_game_does():
    # Entity.get(CUSTOM_NAME) is getCustomName(); DataComponentExactPredicate compares it with the
    # predicate's value decoded by ComponentSerialization.CODEC (MutableComponent.equals: contents,
    # style and siblings): "Tom", {"text": "Tom"} and ["Tom"] are one component, a colour another
    state = WorldState(version=(1, 21, 5))
    props = lambda c: {"condition": "entity_properties", "entity": "this", "predicate": {"components": c}}  # noqa: E731
    plain = state.entities.summon("minecraft:pig", (0.0, 0.0, 0.0), Compound(CustomName=String("Tom")))
    red = state.entities.summon("minecraft:pig", (0.0, 0.0, 0.0), Compound(
        CustomName=Compound(text=String("Tom"), color=String("red"))))
    unnamed = state.entities.summon("minecraft:pig", (0.0, 0.0, 0.0))
    for wanted in ("Tom", {"text": "Tom"}, ["Tom"], {"type": "text", "text": "Tom", "extra": []}):
        assert holds(props({"minecraft:custom_name": wanted}), ctx(state, this=plain))
        assert not holds(props({"minecraft:custom_name": wanted}), ctx(state, this=red))
    assert holds(props({"custom_name": {"text": "Tom", "color": "red"}}), ctx(state, this=red))
    assert not holds(props({"custom_name": {"text": "Tom", "bold": False}}), ctx(state, this=plain))
    assert not holds(props({"custom_name": "Tom"}), ctx(state, this=unnamed))  # no component: no match
    # a name saved as a compound (1.21.5+ SNBT) is kept as it was: data get reads it back
    assert red.display_name == "Tom" and entity_nbt(red)["CustomName"] == Compound(text=String("Tom"),
                                                                                    color=String("red"))


def test_the_entity_predicates_field_reads_the_components_entities_expose():
    # DataComponentMatchers.test (1.21.5+): each sub-predicate reads its component through
    # Entity.get, and a missing component fails (SingleComponentItemPredicate.matches); a villager
    # exposes villager/variant (Villager.get), no entity an item's damage or enchantments
    state = WorldState(version=(1, 21, 11))
    props = lambda p: {"condition": "entity_properties", "entity": "this", "predicate": {"predicates": p}}  # noqa: E731
    villager = state.entities.summon("minecraft:villager", (0.0, 0.0, 0.0), Compound(VillagerData=Compound(
        type=String("minecraft:snow"), profession=String("minecraft:none"), level=Int(1))))
    pig = state.entities.summon("minecraft:pig", (0.0, 0.0, 0.0))
    assert holds(props({"minecraft:villager/variant": "minecraft:snow"}), ctx(state, this=villager))
    assert holds(props({"villager/variant": ["minecraft:desert", "snow"]}), ctx(state, this=villager))
    assert not holds(props({"villager/variant": "minecraft:desert"}), ctx(state, this=villager))
    assert not holds(props({"villager/variant": "minecraft:snow"}), ctx(state, this=pig))
    assert not holds(props({"damage": {}}), ctx(state, this=pig))
    with pytest.raises(Unmodelled, match="custom_data component"):  # before 26.1
        holds(props({"custom_data": {}}), ctx(state, this=pig))
    # before 1.21.5 the entity predicate has no such field: the codec ignores it
    state.version = (1, 21, 4)
    assert holds(props({"damage": {}}), ctx(state, this=pig))


def test_periodic_tick_counts_the_ticks_since_the_entity_came(tmp_path):
    # EntityPredicate.matches: entity.tickCount % periodic_tick == 0; ServerLevel.tickNonPassenger
    # adds one in each tick's entity phase, after the tick's functions: an entity summoned by the
    # load or a tick function holds at once (0) and then every 3rd tick
    from tests.world.world_emulator import make_pack
    from emulator import Emulator
    pack = make_pack(tmp_path / "p", {
        "t:load": "scoreboard objectives add o dummy\nsummon marker 0 0 0 {Tags:['m']}",
        "t:tick": "execute as @e[tag=m] if predicate t:third run scoreboard players add #hits o 1",
    }, {"minecraft:load": ["t:load"], "minecraft:tick": ["t:tick"]})
    (pack / "data/t/predicate").mkdir(parents=True)
    (pack / "data/t/predicate/third.json").write_text(
        '{"condition": "minecraft:entity_properties", "entity": "this", "predicate": {"periodic_tick": 3}}')
    for backend in ("python", "numba"):
        emu = Emulator(backend=backend)
        emu.load(pack)
        emu.tick(7)  # tickCount 0..6 in the functions of ticks 0..6: 0, 3 and 6 hold
        assert emu.score("#hits", "o") == 3, backend
        late = emu.state.entities.summon("minecraft:pig", (0.0, 0.0, 0.0))
        emu.tick(1)
        assert (emu.state.tick - late.born) == 1


def test_an_entitys_custom_data_component_is_its_data_from_26_1():
    # 26.1 Entity.get(CUSTOM_DATA): the entity's ``data`` (CustomData.EMPTY when none); the exact
    # components field compares it whole, the custom_data sub-predicate (NbtPredicate.matches over
    # getOrDefault(CUSTOM_DATA, EMPTY)) partly; before 26.1 it is not modelled (release unconfirmed).
    # A JSON object is read by CompoundTag.CODEC (JsonOps.convertTo: 1 is the byte 1b), so it does
    # not match an int 1 that SNBT ``{a:1}`` does
    state = WorldState(version=(26, 1, 0))
    field = lambda key, value: {"condition": "entity_properties", "entity": "this", "predicate": {  # noqa: E731
        key: {"minecraft:custom_data": value}}}
    tagged = state.entities.summon("minecraft:pig", (0.0, 0.0, 0.0), Compound(data=Compound(a=Byte(1), b=String("x"))))
    wide = state.entities.summon("minecraft:pig", (0.0, 0.0, 0.0), Compound(data=Compound(a=Int(1))))
    plain = state.entities.summon("minecraft:pig", (0.0, 0.0, 0.0))
    assert holds(field("predicates", {"a": 1}), ctx(state, this=tagged))
    assert not holds(field("predicates", {"a": 1}), ctx(state, this=wide))
    assert holds(field("predicates", "{a:1}"), ctx(state, this=wide))
    assert holds(field("predicates", "{b:'x'}"), ctx(state, this=tagged))
    assert not holds(field("predicates", {"a": 2}), ctx(state, this=tagged))
    assert holds(field("predicates", {}), ctx(state, this=plain))
    assert holds(field("components", {"a": 1, "b": "x"}), ctx(state, this=tagged))
    assert not holds(field("components", {"a": 1}), ctx(state, this=tagged))
    assert holds(field("components", {}), ctx(state, this=plain))
    state.version = (1, 21, 11)
    with pytest.raises(Unmodelled, match="custom_data"):
        holds(field("components", {}), ctx(state, this=plain))


def test_a_json_item_predicate_reads_custom_data_as_compound_tag_codec_does(state):
    # ItemPredicate's ``components`` (DataComponentPredicate: CustomData.CODEC) and ``predicates``
    # custom_data (NbtPredicate: TagParser.LENIENT_CODEC) read a JSON object through
    # CompoundTag.CODEC (JsonOps.convertTo: 1 is 1b), SNBT text through TagParser
    byte_one = ItemStack("minecraft:stone", 1, Compound({"minecraft:custom_data": Compound(a=Byte(1))}))
    int_one = ItemStack("minecraft:stone", 1, Compound({"minecraft:custom_data": Compound(a=Int(1))}))
    exact = {"items": "minecraft:stone", "components": {"minecraft:custom_data": {"a": 1}}}
    partial = {"predicates": {"minecraft:custom_data": {"a": 1}}}
    text = {"predicates": {"minecraft:custom_data": "{a:1}"}}
    state.version = (1, 21, 4)
    matches = lambda predicate, stack: predicates.item_matches(predicate, ctx(state), stack)  # noqa: E731
    assert matches(exact, byte_one) and not matches(exact, int_one)
    assert matches(partial, byte_one) and not matches(partial, int_one)
    assert matches(text, int_one) and not matches(text, byte_one)
