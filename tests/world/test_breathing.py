"""A player's air under water (emulator.world.breathing). Sources (decompiled): LivingEntity.baseTick
(1.21.3, 1.21.7, 26.1.2: the air under water, drowning, refilling), decreaseAirSupply,
increaseAirSupply, shouldTakeDrowningDamage; Entity.updateFluidOnEyes; MobEffectUtil.hasWaterBreathing."""
import pytest

from emulator.api import Emulator
from emulator.world import breathing, combat
from emulator.world.blocks import BlockState
from emulator.world.resources import RegistryTag, Resources
from emulator.world.state import WorldState
from mcfunction_parser.nbt import Byte, Compound, Int, List, String
from tests.conftest import write_pack

WATER = BlockState("minecraft:water", (("level", "0"),))


def _world(version=(1, 21, 4), resources=None):
    state = WorldState(resources=resources or Resources(), version=version)
    player = state.entities.add_player("Alex", (0.5, 64.0, 0.5))
    return state, player, state.blocks_in(player.dimension)


def _ticks(state, n):
    for _ in range(n):
        breathing.tick_air(state, combat.hurt)


def _effect(player, effect_id):
    player.data["active_effects"] = List([Compound(id=String(effect_id), amplifier=Byte(0), duration=Int(600))])


def test_eyes_in_water_lose_a_breath_a_tick_and_drown_at_minus_20():
    # baseTick: decreaseAirSupply 1 a tick from 300; at -20 the air is 0 and drown hurts 2
    state, player, blocks = _world()
    blocks.set_state((0, 65, 0), WATER)  # the eyes' cell (64 + 1.62): its top 65 + 8/9 is above them
    _ticks(state, 319)
    assert breathing.air(player) == -19 and float(player.data["Health"]) == 20.0
    _ticks(state, 1)
    assert breathing.air(player) == 0 and float(player.data["Health"]) == 18.0
    assert player.data["Air"].__class__.__name__ == "Short"


def test_out_of_water_the_air_comes_back_four_a_tick():
    state, player, _ = _world()
    breathing.set_air(player, 290)
    _ticks(state, 2)
    assert breathing.air(player) == 298
    _ticks(state, 1)
    assert breathing.air(player) == 300  # increaseAirSupply: at most the maximum


def test_water_below_the_eyes_is_not_over_them():
    # updateFluidOnEyes: only the eyes' cell counts; water at the feet leaves the eyes dry
    state, player, blocks = _world()
    blocks.set_state((0, 64, 0), WATER)
    _ticks(state, 5)
    assert breathing.air(player) == 300


def test_creative_players_and_water_breathing_keep_their_air():
    # canDrownInWater: Abilities.invulnerable, MobEffectUtil.hasWaterBreathing
    state, player, blocks = _world()
    blocks.set_state((0, 65, 0), WATER)
    player.gamemode = "creative"
    _ticks(state, 5)
    assert breathing.air(player) == 300
    player.gamemode = "survival"
    _effect(player, "minecraft:water_breathing")
    _ticks(state, 5)
    assert breathing.air(player) == 300


@pytest.mark.parametrize("version, after", [((1, 21, 3), 100), ((1, 21, 4), 120), ((1, 21, 7), 120)])
def test_one_that_cannot_drown_gets_air_back_under_water_from_1_21_4(version, after):
    # 1.21.3 baseTick: no change under water; 1.21.4 and 1.21.7: increaseAirSupply when it cannot drown
    state, player, blocks = _world(version)
    blocks.set_state((0, 65, 0), WATER)
    _effect(player, "minecraft:water_breathing")
    breathing.set_air(player, 100)
    _ticks(state, 5)
    assert breathing.air(player) == after


def test_a_bubble_column_gives_air():
    # baseTick: eyes in a bubble column take the else branch (increaseAirSupply)
    state, player, blocks = _world()
    blocks.set_state((0, 65, 0), BlockState("minecraft:bubble_column", (("drag", "true"),)))
    breathing.set_air(player, 100)
    _ticks(state, 1)
    assert breathing.air(player) == 104


def test_a_pack_tag_can_let_players_breathe_water():
    # LivingEntity.canBreatheUnderwater: #minecraft:can_breathe_under_water (from 1.20.5)
    resources = Resources(tags={"entity_type": {breathing.BREATHERS_TAG: RegistryTag(frozenset({"minecraft:player"}))}})
    state, player, blocks = _world(resources=resources)
    blocks.set_state((0, 65, 0), WATER)
    _ticks(state, 5)
    assert breathing.air(player) == 300


def test_a_mob_under_water_is_not_modelled():
    state, player, blocks = _world()
    state.entities.summon("minecraft:zombie", (3.5, 64.0, 0.5), {"NoAI": Byte(1)})
    blocks.set_state((3, 65, 0), WATER)
    _ticks(state, 1)
    assert [d.message for d in state.diagnostics if d.unmodelled] == [
        "air under water: the air of minecraft:zombie (its type's own breathing)"]


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_a_player_in_a_pool_drowns_as_the_game_counts(tmp_path, backend):
    # a client's player held under water by the API: 300 ticks of air, then -1 to -20 and the
    # drowning's 2 damage every 20 ticks after
    root = write_pack(tmp_path / "p", {"t/function/load.mcfunction": "fill -1 64 -1 1 66 1 water\n"
                                                                     "scoreboard objectives add air dummy\n"
                                                                     "scoreboard objectives add hurt "
                                                                     "minecraft.custom:minecraft.damage_taken\n",
                                       "t/function/read.mcfunction":
                                       "execute as Alex store result score @s air run data get entity @s Air"},
                      load=["t:load"])
    emu = Emulator(backend=backend)
    emu.load(root)
    emu.start()
    emu.add_player("Alex", (0.5, 64.0, 0.5))
    emu.tick(355)
    emu.call("t:read")
    assert emu.score("Alex", "air") == -15  # drowned at ticks 320 and 340 (air to 0), then 15 more breaths
    assert emu.score("Alex", "hurt") == 40  # 2 x 2 damage, in tenths (damage_taken)


@pytest.mark.parametrize("version", [(1, 20, 6), (1, 21, 4)])
def test_a_respiration_helmet_keeps_air_by_chance_not_modelled(version):
    # decreaseAirSupply: a chance from the helmet's respiration (1.20.6: EnchantmentHelper.getRespiration)
    # or the oxygen_bonus attribute it gives (1.21+): the player's random
    from emulator.world import inventories
    from emulator.world.items import ItemStack, set_component
    state, player, blocks = _world(version)
    blocks.set_state((0, 65, 0), WATER)
    helmet = ItemStack("minecraft:iron_helmet")
    set_component(helmet, "minecraft:enchantments", Compound(levels=Compound({"minecraft:respiration": Int(1)})))
    inventories.entity_slot(player, inventories.ARMOR_SLOTS["head"], version).set(helmet)
    _ticks(state, 1)
    assert breathing.air(player) == 300  # left as it was
    assert [d.message for d in state.diagnostics if d.unmodelled] == [
        "air under water: air kept by chance (an oxygen bonus: respiration)"]
