"""The predicate engine (emulator.world.predicates) against the game's rules, each pinned to its
source (decompiled 1.21, net/minecraft/world/level/storage/loot/predicates and
advancements/critereon)."""
from __future__ import annotations

import pytest

from emulator.world import predicates
from emulator.world.blocks import BlockSpec
from emulator.world.errors import Unmodelled
from emulator.world.predicates import LootContext, test as holds
from emulator.world.resources import Resources
from emulator.world.state import WorldState
from mcfunction_parser.pack.conditions import parse_inline
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
    # a state the block was placed without: its default is not known here, said so
    with pytest.raises(Unmodelled, match="half"):
        holds({"condition": "location_check", "offsetY": 1,
              "predicate": {"block": {"state": {"half": "bottom"}}}}, ctx(state, origin=(0.5, 0.2, 0.5)))


def test_command_parameter_set_lacks_tool_block_and_damage(state):
    # ExecuteCommand.checkCustomPredicate uses LootContextParamSets.COMMAND: origin and this only
    assert not holds({"condition": "match_tool"}, ctx(state))
    assert not holds({"condition": "block_state_property", "block": "minecraft:stone"}, ctx(state))
    assert not holds({"condition": "killed_by_player"}, ctx(state))
    assert holds({"condition": "survives_explosion"}, ctx(state))  # ExplosionCondition: no radius -> true
    assert not holds({"condition": "damage_source_properties"}, ctx(state))


def test_match_tool_item_predicate(state):
    # MatchTool + ItemPredicate: items, count, components (exact), predicates.custom_data (partial)
    stack = Compound(id=String("minecraft:stick"), count=Int(3),
                     components=Compound({"minecraft:custom_data": Compound(magic=Byte(1), more=Int(2))}))
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
    with pytest.raises(Unmodelled, match="equipment"):
        holds(props({"equipment": {"mainhand": {"items": "minecraft:stick"}}}), this)
    with pytest.raises(Unmodelled, match="'minecraft:nope'"):
        holds({"condition": "minecraft:nope"}, this)


def test_inline_predicates_read_snbt():
    # 1.20.5+ inline predicates: SNBT read through the condition codec
    value = parse_inline('{condition:"minecraft:random_chance",chance:0.5f}')
    assert value == {"condition": "minecraft:random_chance", "chance": pytest.approx(0.5)}
