"""Eyes inside a block (emulator.world.suffocation): Entity.isInWall and LivingEntity.baseTick's
in_wall hurt (decompiled 26.1.2 and 1.21.3; Blocks.java's isSuffocating)."""
import pytest

from emulator.api import Emulator
from emulator.world import combat, suffocation
from emulator.world.blocks import BlockState
from emulator.world.resources import Resources
from emulator.world.state import WorldState
from mcfunction_parser.nbt import Byte
from tests.conftest import write_pack


def _world():
    state = WorldState(resources=Resources(), version=(1, 21, 4))
    player = state.entities.add_player("Alex", (0.5, 64.0, 0.5))
    return state, player, state.blocks_in(player.dimension)


def _health(entity) -> float:
    return float(entity.data["Health"])


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_eyes_in_stone_take_one_in_wall_damage_each_hurt_time(tmp_path, backend):
    # baseTick hurts 1 each tick; LivingEntity's invulnerable time (20, a hurt again at 10) lets one
    # through in 10 ticks
    root = write_pack(tmp_path / "p", {"t/function/load.mcfunction":
                                       "setblock 0 65 0 stone\n"
                                       "scoreboard objectives add hurt minecraft.custom:minecraft.damage_taken\n"},
                      load=["t:load"])
    emu = Emulator(backend=backend)
    emu.load(root)
    emu.start()
    emu.add_player("Alex", (0.5, 64.0, 0.5))
    emu.tick(59)  # its spawn protection (ServerPlayer.spawnInvulnerableTime, up to 1.21.3: 60 at first,
    assert emu.score("Alex", "hurt") is None  # one less first thing in each of its ticks)
    emu.tick(21)
    assert emu.score("Alex", "hurt") == 30  # ticks 60, 70 and 80, in tenths


@pytest.mark.parametrize("block, walled", [("minecraft:glass", False), ("minecraft:oak_leaves", False),
                                           ("minecraft:white_stained_glass", False), ("minecraft:stone", True),
                                           ("minecraft:barrier", True), ("minecraft:torch", False)])
def test_which_blocks_suffocate(block, walled):
    # Blocks: glass, stained glass and leaves are isSuffocating(never); a full cube suffocates; a
    # block without collision cannot meet the eyes' box
    state, player, blocks = _world()
    blocks.set_state((0, 65, 0), BlockState(block))
    assert suffocation.in_wall(state, player) is walled


def test_the_eyes_box_is_four_fifths_of_the_width():
    # isInWall: 0.8 x 0.6 = 0.48 wide around x 0.5 reaches 0.26 - 0.74: not the next column's block
    state, player, blocks = _world()
    blocks.set_state((1, 65, 0), BlockState("minecraft:stone"))
    assert not suffocation.in_wall(state, player)
    player.pos = (0.8, 64.0, 0.5)  # now 0.56 - 1.04
    assert suffocation.in_wall(state, player)


def test_soul_sand_suffocates_only_up_to_its_collision_top():
    # SoulSandBlock's collision shape is 14/16 high; isSuffocating(always)
    state, player, blocks = _world()
    blocks.set_state((0, 65, 0), BlockState("minecraft:soul_sand"))
    assert suffocation.in_wall(state, player)  # eyes at 65.62 < 65.875
    player.pos = (0.5, 64.3, 0.5)  # eyes at 65.92
    assert not suffocation.in_wall(state, player)


def test_spectators_and_armor_stands_are_spared():
    state, player, blocks = _world()
    blocks.set_state((0, 65, 0), BlockState("minecraft:stone"))
    player.gamemode = "spectator"  # noPhysics
    stand = state.entities.summon("minecraft:armor_stand", (0.5, 64.0, 0.5), {"NoGravity": Byte(1)})
    suffocation.tick_in_wall(state, combat.hurt)
    assert _health(player) == 20.0 and _health(stand) == 20.0
    assert suffocation.tick_is_idle(state)


def test_a_shape_not_known_here_is_not_modelled():
    state, player, blocks = _world()
    blocks.set_state((0, 65, 0), BlockState("minecraft:oak_slab", (("type", "top"), ("waterlogged", "false"))))
    suffocation.tick_in_wall(state, combat.hurt)
    assert any("eyes in a block" in d.message for d in state.diagnostics if d.unmodelled)
