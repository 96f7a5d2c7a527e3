"""What block entities do each tick (their BlockEntityTicker on the server), after the entities,
as far as the emulator models it; what it does not is reported as not modelled, once per kind.

- ``tick_block_entities(state)``: every level's ticking block entities, in each level's order:
  an end gateway's ``Age`` grows; a hopper's ``TransferCooldown`` counts down and at 0 it moves
  items (:mod:`emulator.world.hoppers`); furnaces, smokers and blast furnaces burn and cook
  (:mod:`emulator.world.furnaces`); a jukebox plays its song (:mod:`emulator.world.jukeboxes`);
  a brewing stand brews (:mod:`emulator.world.brewing`); an unlit campfire's cooking progress
  falls back by 2; a spawner counts its ``Delay`` down while a living player who is no spectator
  is within ``RequiredPlayerRange``. A lit campfire cooking, spawning, bees leaving a hive and a
  beacon over blocks are not modelled, nor is what those modules name.
  ``tick_is_idle(state)``: nothing would change.

Sources (decompiled 1.21): world/level/block/entity/TheEndGatewayBlockEntity.portalTick,
HopperBlockEntity.pushItemsTick / tryMoveItems / suckInItems, AbstractFurnaceBlockEntity.serverTick,
CampfireBlockEntity.cookTick / cooldownTick, BrewingStandBlockEntity.serverTick,
world/level/BaseSpawner.serverTick / isNearPlayer (Level.hasNearbyAlivePlayer),
BeaconBlockEntity.tick (every 80 ticks: updateBase), BeehiveBlockEntity.serverTick,
JukeboxBlockEntity.tick.
"""
from __future__ import annotations

from emulator.world import block_entities, brewing, furnaces, hoppers, jukeboxes
from emulator.world.errors import Unmodelled
from emulator.world.nbt_ops import int_at
from mcfunction_parser.nbt import Int, Long, Short

MESSAGE = "{} working (what a block entity does each tick beyond its counters is not modelled here)"



def _reported(state, message: str) -> bool:
    return any(d.message == message for d in state.diagnostics)


def _report(state, message: str) -> None:
    if not _reported(state, message):
        state.error(message, severity="warning", unmodelled=True)


def _levels(state):
    yield "minecraft:overworld", state.blocks
    yield from state.other_levels_blocks.items()


# the hoppers that ticked so far this tick (HopperBlockEntity.tickedGameTime is this game time)
_TICKED: set = set()


def _nothing_to_tick(state) -> bool:
    """No block entity in any level and no minecart (a hopper minecart's work is reported here): the
    common world, every tick."""
    others = state.other_levels_blocks
    return (not state.blocks.entities and not state.entities.minecarts()
            and not (others and any(blocks.entities for blocks in others.values())))


def tick_block_entities(state) -> None:
    if _nothing_to_tick(state):
        return
    cart = hoppers.minecart_would_pull(state)  # an entity's work, reported with the hoppers'
    if cart is not None:
        _report(state, cart)
    for dimension, blocks in _levels(state):
        _TICKED.clear()
        for pos, nbt in list(blocks.entities.items()):
            if blocks.entity(pos) is not nbt:  # removed or replaced by an earlier one's work
                continue
            tick = _TICKS.get(block_entities.type_id(blocks.get(pos).id))
            if tick is None:
                continue
            try:
                tick(state, dimension, blocks, pos, nbt)
            except Unmodelled as reason:
                _report(state, reason.reason)
            if blocks.get(pos).id == "minecraft:hopper":
                _TICKED.add(pos)
    _TICKED.clear()


def tick_is_idle(state) -> bool:
    if _nothing_to_tick(state):
        return True
    cart = hoppers.minecart_would_pull(state)
    if cart is not None and not _reported(state, cart):
        return False
    for dimension, blocks in _levels(state):
        for pos, nbt in blocks.entities.items():
            idle = _IDLE.get(block_entities.type_id(blocks.get(pos).id))
            try:
                if idle is not None and not idle(state, dimension, blocks, pos, nbt):
                    return False
            except Unmodelled:
                return False
    return True


# ---------------------------------------------------------------------- each kind
def _gateway(state, dimension, blocks, pos, nbt) -> None:
    """TheEndGatewayBlockEntity.portalTick: the age grows every tick (its cooldown is not saved)."""
    nbt["Age"] = Long(int_at(nbt, "Age") + 1)


def _hopper(state, dimension, blocks, pos, nbt) -> None:
    """HopperBlockEntity.pushItemsTick: the cooldown counts down; at 0 or below it is set to 0 and
    the hopper moves items (:func:`emulator.world.hoppers.transfer`)."""
    cooldown = int_at(nbt, "TransferCooldown") - 1
    if cooldown > 0:
        nbt["TransferCooldown"] = Int(cooldown)
        return
    nbt["TransferCooldown"] = Int(0)
    hoppers.transfer(state, dimension, blocks, pos, nbt, _TICKED)


def _hopper_idle(state, dimension, blocks, pos, nbt) -> bool:
    return int_at(nbt, "TransferCooldown") == 0 and hoppers.still(state, dimension, blocks, pos, nbt)


def _furnace(state, dimension, blocks, pos, nbt) -> None:
    furnaces.tick(state, blocks, pos, nbt)


def _furnace_idle(state, dimension, blocks, pos, nbt) -> bool:
    return furnaces.idle(state, blocks.get(pos).id, nbt)


def _campfire(state, dimension, blocks, pos, nbt) -> None:
    """CampfireBlockEntity: a lit one cooks its items (not modelled); an unlit one lets each
    slot's progress fall back by 2 (cooldownTick)."""
    lit = dict(blocks.get(pos).properties).get("lit") == "true"
    times, totals = list(nbt.get("CookingTimes") or []), list(nbt.get("CookingTotalTimes") or [])
    if lit:
        if nbt.get("Items"):
            _report(state, MESSAGE.format("a lit campfire cooking"))
        return
    if any(int(t) > 0 for t in times):
        totals += [0] * (len(times) - len(totals))
        nbt["CookingTimes"] = type(nbt["CookingTimes"])(
            Int(min(max(int(t) - 2, 0), int(total))) if int(t) > 0 else Int(int(t)) for t, total in zip(times, totals))


def _campfire_idle(state, dimension, blocks, pos, nbt) -> bool:
    lit = dict(blocks.get(pos).properties).get("lit") == "true"
    return not (lit and nbt.get("Items")) and not any(int(t) > 0 for t in nbt.get("CookingTimes") or [])


def _player_near(state, dimension, pos, nbt) -> bool:
    """BaseSpawner.isNearPlayer: a living player who is no spectator within the range of the
    block's centre (any distance when the range is negative)."""
    reach = int_at(nbt, "RequiredPlayerRange", 16)
    centre = tuple(c + 0.5 for c in pos)
    for player in state.entities.players():
        if player.dimension != dimension or player.gamemode == "spectator" or player in state.dead_players:
            continue
        if reach < 0 or sum((a - b) ** 2 for a, b in zip(player.pos, centre)) < reach * reach:
            return True
    return False


def _spawner(state, dimension, blocks, pos, nbt) -> None:
    """BaseSpawner.serverTick near a player: the delay counts down; at 0 it spawns (not modelled)."""
    if not _player_near(state, dimension, pos, nbt):
        return
    delay = int_at(nbt, "Delay", 20)
    if delay > 0:
        nbt["Delay"] = Short(delay - 1)
    else:
        _report(state, MESSAGE.format("a spawner spawning"))


def _spawner_idle(state, dimension, blocks, pos, nbt) -> bool:
    return not _player_near(state, dimension, pos, nbt)


def _beacon(state, dimension, blocks, pos, nbt) -> None:
    """BeaconBlockEntity.tick: every 80 game ticks its levels are counted from the pyramid under
    it; with no level and nothing under it that stays 0, anything else is not modelled."""
    if state.gametime % 80 == 0 and not _beacon_idle(state, dimension, blocks, pos, nbt):
        _report(state, MESSAGE.format("a beacon"))


def _beacon_idle(state, dimension, blocks, pos, nbt) -> bool:
    x, y, z = pos
    return int_at(nbt, "Levels") == 0 and all(blocks.get((x + dx, y - 1, z + dz)).is_air
                                            for dx in (-1, 0, 1) for dz in (-1, 0, 1))


def _jukebox(state, dimension, blocks, pos, nbt) -> None:
    jukeboxes.tick(state, blocks, pos, nbt)


def _jukebox_idle(state, dimension, blocks, pos, nbt) -> bool:
    return jukeboxes.idle(state, nbt)


def _busy_when(key: str, what: str):
    """A block entity that works only while ``key`` holds something (a hive's bees)."""
    def tick(state, dimension, blocks, pos, nbt) -> None:
        if nbt.get(key):
            _report(state, MESSAGE.format(what))

    def idle(state, dimension, blocks, pos, nbt) -> bool:
        return not nbt.get(key)
    return tick, idle


_HIVE = _busy_when("bees", "a beehive with bees")
_OLD_HIVE = _busy_when("Bees", "a beehive with bees")
_TICKS = {
    "minecraft:end_gateway": _gateway, "minecraft:hopper": _hopper, "minecraft:campfire": _campfire,
    "minecraft:brewing_stand": brewing.tick, "minecraft:mob_spawner": _spawner, "minecraft:beacon": _beacon,
    "minecraft:beehive": lambda *a: (_HIVE[0](*a), _OLD_HIVE[0](*a)), "minecraft:jukebox": _jukebox,
    **{f: _furnace for f in furnaces.FURNACES},
}
_IDLE = {
    "minecraft:end_gateway": lambda *a: False, "minecraft:hopper": _hopper_idle, "minecraft:campfire": _campfire_idle,
    "minecraft:brewing_stand": brewing.idle, "minecraft:mob_spawner": _spawner_idle, "minecraft:beacon": _beacon_idle,
    "minecraft:beehive": lambda *a: _HIVE[1](*a) and _OLD_HIVE[1](*a), "minecraft:jukebox": _jukebox_idle,
    **{f: _furnace_idle for f in furnaces.FURNACES},
}
