"""What a player looks at (:mod:`emulator.world.sight`): PlayerPredicate's ``looking_at`` from
the eyes along the view vector, AABB.clip's entry faces, and the line of sight."""
from __future__ import annotations

import pytest

from emulator.world.blocks import parse_block
from emulator.world.errors import Unmodelled
from emulator.world.ray import clip
from emulator.world.sight import looked_at
from emulator.world.state import WorldState
from mcfunction_parser.nbt import Compound, Float


def test_clip_finds_the_entry_face_and_nothing_from_inside():
    box = (0.0, 0.0, 0.0, 1.0, 1.0, 1.0)
    assert clip(box, (-1.0, 0.5, 0.5), (2.0, 0.5, 0.5)) == (0.0, 0.5, 0.5)
    assert clip(box, (2.0, 0.5, 0.5), (-1.0, 0.5, 0.5)) == (1.0, 0.5, 0.5)
    assert clip(box, (0.5, 0.5, 0.5), (2.0, 0.5, 0.5)) is None  # AABB.clip: a start inside enters nothing
    assert clip(box, (-1.0, 2.0, 0.5), (2.0, 2.0, 0.5)) is None
    assert clip(box, (-1.0, 0.5, 0.5), (-0.5, 0.5, 0.5)) is None  # the segment ends before the box


def test_the_nearest_entity_in_view_and_an_interactions_own_size():
    state = WorldState()
    steve = state.entities.add_player("Steve", (0.5, 0.0, 0.5), yaw=180.0)  # facing north (-z)
    far = state.entities.summon("minecraft:interaction", (0.5, 0.0, -5.5), Compound(width=Float(1.0), height=Float(2.0)))
    assert looked_at(state, steve) is far
    near = state.entities.summon("minecraft:interaction", (0.5, 0.0, -2.5))  # 1 x 1 by default
    assert looked_at(state, steve) is far  # the eyes (1.62) pass over the 1-high box
    near_tall = state.entities.summon("minecraft:interaction", (0.5, 0.0, -3.5), Compound(height=Float(3.0)))
    assert looked_at(state, steve) is near_tall and near.eye_height == pytest.approx(0.85)
    steve.yaw = 0.0
    assert looked_at(state, steve) is None


def test_a_block_in_the_line_of_sight_is_not_modelled():
    state = WorldState()
    steve = state.entities.add_player("Steve", (0.5, 0.0, 0.5), yaw=180.0)
    state.entities.summon("minecraft:interaction", (0.5, 0.0, -3.5), Compound(height=Float(2.0)))
    state.blocks.setblock((0, 1, -1), parse_block("minecraft:glass"))
    with pytest.raises(Unmodelled, match="line of sight"):
        looked_at(state, steve)
