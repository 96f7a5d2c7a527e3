"""Entity predicates in the 26.2 sub-predicate form (EntitySubPredicates: a map of sub-predicate
ids, ``entity_type`` for the old ``type``, ``type_specific/<kind>`` for the old ``type_specific``,
the new ``entity_tags``), read by :mod:`emulator.world.entity_predicate_format`."""
from __future__ import annotations

import pytest

from emulator.world.entity_predicate_format import classic
from emulator.world.errors import Unmodelled
from emulator.world.predicates import LootContext, test as holds
from emulator.world.state import WorldState


@pytest.fixture
def state():
    state = WorldState()
    state.version = (26, 2, 0)
    return state


def properties(predicate: dict) -> dict:
    return {"condition": "entity_properties", "entity": "this", "predicate": predicate}


def test_the_sub_predicate_ids_read_as_the_old_fields():
    written = {"minecraft:entity_type": "#minecraft:undead", "flags": {"is_on_fire": True},
               "type_specific/player": {"gamemode": ["creative"]}, "minecraft:type_specific/cube_mob": {"size": 2}}
    assert classic(written, (26, 2, 0)) == {"type": "#minecraft:undead", "flags": {"is_on_fire": True},
                                            "type_specific": {"type": "slime", "size": 2}}
    # before 26.2 a predicate is read as written (the old record's fields)
    assert classic(written, (26, 1, 2)) is written


def test_entity_tags_all_any_and_none_of(state):
    pig = state.entities.summon("minecraft:pig", (0.0, 0.0, 0.0))
    pig.tags.add("a")
    pig.tags.add("b")
    ctx = LootContext(state, (0.0, 0.0, 0.0), this=pig)
    assert holds(properties({"minecraft:entity_type": "pig", "entity_tags": {"all_of": ["a", "b"]}}), ctx)
    assert not holds(properties({"entity_tags": {"all_of": ["a", "c"]}}), ctx)
    assert holds(properties({"entity_tags": {"any_of": ["c", "b"]}}), ctx)
    assert not holds(properties({"entity_tags": {"any_of": ["c"]}}), ctx)
    assert not holds(properties({"entity_tags": {"none_of": ["b"]}}), ctx)
    assert not holds(properties({"minecraft:entity_type": "cow"}), ctx)


def test_the_player_sub_predicate_and_an_unknown_id(state):
    steve = state.entities.add_player("Steve", (0.0, 0.0, 0.0), gamemode="creative")
    ctx = LootContext(state, (0.0, 0.0, 0.0), this=steve)
    assert holds(properties({"type_specific/player": {"gamemode": ["creative", "spectator"]}}), ctx)
    assert not holds(properties({"minecraft:type_specific/player": {"gamemode": ["survival"]}}), ctx)
    with pytest.raises(Unmodelled, match="sub-predicate 'minecraft:wetness'"):
        holds(properties({"minecraft:wetness": {}}), ctx)
