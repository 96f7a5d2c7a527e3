"""Relations between entities: riding (``Passengers`` in summon NBT, ``ride``) and the owners named
by UUID, for ``execute on <relation>``.

Sources (decompiled 1.21): commands/ExecuteCommand (``on``: expandOneToOneEntityRelation /
expandOneToManyEntityRelation; only the executor changes, removed entities are skipped, no executor
gives no context), world/entity/EntityType.loadEntityRecursive (each ``Passengers`` compound is
loaded and starts riding its vehicle, forced), server/level/ServerLevel.tryAddFreshEntityWithPassengers
(the vehicle is added first, then its passengers depth first), world/entity/Entity.startRiding
(a vehicle that cannot accept passengers, the current vehicle, or a loop refuses), Marker
(couldAcceptPassenger false); ``ride`` itself is :func:`emulator.commands.entities.ride`.
``owner`` follows the ``Owner`` UUID of tameable animals and horses (OwnableEntity); ``origin``
follows ``Owner`` of projectiles, evoker fangs and area effect clouds and ``Thrower`` of items
(TraceableEntity). ``target`` and ``attacker`` (ExecuteCommand: Targeting.getTarget,
Attackable.getLastAttacker): an interaction entity's are the players in its level whose UUIDs its
``interaction`` and ``attack`` records name (Interaction.getTarget / getLastAttacker, through
Level.getPlayerByUUID); a living entity's attacker is the last living entity to hurt it within 100
ticks (LivingEntity.getLastHurtByMob, emulator.world.combat); a mob's target comes from its AI,
which is not modelled (Unmodelled), except for a mob with ``NoAI``, whose goals never run: none.
``controller`` (Entity.getControllingPassenger): a boat's is its first passenger when living
(Boat); an entity that is neither a boat nor a Mob has none (Entity); a Mob's depends on its AI,
saddles and held items (Mob, Pig, AbstractHorse, Strider), which are not modelled (Unmodelled) once
it carries someone. ``leasher`` (Leashable.getLeashHolder): only Mobs and boats are Leashable, and
one without ``leash`` data has no holder; a leash that is there is not modelled (Unmodelled).
"""
from __future__ import annotations

import numpy as np

from emulator.world import advancements, combat, living, mth
from emulator.world.dimensions import OVERWORLD
from emulator.world.entities import Entity, EntityStore
from emulator.world.entity_types import BOATS
from emulator.world.errors import CommandFailure, Unmodelled
from mcfunction_parser.nbt import Compound, IntArray, List, String
from mcfunction_parser.pack.tags import normalise_id

INTERACTION = "minecraft:interaction"
F32 = np.float32
_NO_PASSENGERS = frozenset({"minecraft:marker"})
_OWNABLE = frozenset(f"minecraft:{t}" for t in (
    "wolf", "cat", "parrot", "horse", "donkey", "mule", "llama", "trader_llama", "skeleton_horse",
    "zombie_horse", "camel"))
_TRACEABLE = {f"minecraft:{t}": "Owner" for t in (
    "arrow", "spectral_arrow", "trident", "snowball", "egg", "ender_pearl", "experience_bottle", "potion",
    "splash_potion", "lingering_potion", "fireball", "small_fireball", "dragon_fireball", "wither_skull",
    "shulker_bullet", "llama_spit", "firework_rocket", "wind_charge", "breeze_wind_charge", "evoker_fangs",
    "area_effect_cloud")}
_TRACEABLE["minecraft:item"] = "Thrower"


def vehicle_of(entity: Entity) -> Entity | None:
    v = entity.vehicle
    return v if v is not None and v.alive else None


def passengers_of(entity: Entity) -> list[Entity]:
    return [p for p in entity.passengers if p.alive]


def start_riding(rider: Entity, vehicle: Entity) -> bool:
    """Entity.startRiding(vehicle, force=true): False when refused."""
    if vehicle is vehicle_of(rider) or vehicle.type in _NO_PASSENGERS:
        return False
    carrier = vehicle
    while vehicle_of(carrier) is not None:
        carrier = vehicle_of(carrier)
        if carrier is rider:
            return False
    stop_riding(rider)
    rider.vehicle = vehicle
    vehicle.passengers.append(rider)
    return True


def started_riding(state, vehicle: Entity) -> None:
    """Entity.startRiding: each player among the vehicle's passengers, at any depth, hears
    ``started_riding`` (getIndirectPassengersStream)."""
    for rider in self_and_passengers(vehicle)[1:]:
        if rider.is_player:
            advancements.trigger(state, rider, "started_riding")


# EntityType passengerAttachments (the first passenger's height on the vehicle) and the player's
# vehicle attachment (Player.DEFAULT_VEHICLE_ATTACHMENT): where a player rides
PASSENGER_ATTACHMENT = {"minecraft:pig": float(F32(0.86875)), "minecraft:minecart": float(F32(0.1875))}
PLAYER_VEHICLE_ATTACHMENT = 0.6
BOAT_HEIGHT = F32(0.5625)  # EntityType.BOAT: sized(1.375F, 0.5625F)


def _passenger_attachment(vehicle: Entity) -> float | None:
    """The first passenger's height on ``vehicle``: the type's passengerAttachments, a boat's a third
    of its height, a raft's 0.8888889 of it (Boat.getPassengerAttachmentPoint); None when not known."""
    if vehicle.type in BOATS and "chest" not in vehicle.type:
        raft = vehicle.type == "minecraft:bamboo_raft" or str(vehicle.data.get("Type", "")) == "bamboo"
        return float(BOAT_HEIGHT * F32(0.8888889) if raft else BOAT_HEIGHT / F32(3.0))
    return PASSENGER_ATTACHMENT.get(vehicle.type)


def position_rider(rider: Entity) -> None:
    """Entity.positionRider for a player riding alone at the vehicle's scale 1: at the vehicle's
    x and z, its passenger attachment less the player's vehicle attachment above its feet."""
    vehicle = rider.vehicle
    attachment = _passenger_attachment(vehicle)
    if attachment is None or not rider.is_player or len(passengers_of(vehicle)) > 1 or \
            (living.is_living(vehicle.type) and living.attribute_value(vehicle, "scale") != 1.0):
        raise Unmodelled(f"where {rider.type} rides on {vehicle.type} (its passenger attachment)")
    x, y, z = vehicle.pos
    rider.pos = (x, y + attachment - PLAYER_VEHICLE_ATTACHMENT, z)
    if vehicle.type in BOATS:  # Boat.clampRotation: the rider looks within 105 degrees of the bow
        turn = mth.wrap_degrees_f(F32(rider.yaw) - F32(vehicle.yaw))
        rider.yaw = F32(rider.yaw) + mth.clamp_f(turn, F32(-105.0), F32(105.0)) - turn


def mount(state, rider: Entity, vehicle: Entity) -> bool:
    """Player.startRiding(vehicle) (not forced): refused when the vehicle already carries someone
    (Entity.canAddPassenger: one rider for the vehicles modelled here); the rider goes onto the
    vehicle's attachment at once (ServerPlayer.startRiding -> positionRider) and every player riding
    it hears ``started_riding``."""
    if passengers_of(vehicle) or not start_riding(rider, vehicle):
        return False
    position_rider(rider)
    started_riding(state, vehicle)
    return True


def ride_tick(rider: Entity) -> None:
    """Player.rideTick on the server: a sneaking player gets off (wantsToStopRiding: where it is put
    down, Entity.dismountTo, is not modelled); else Entity.rideTick: no motion, and the vehicle
    places it (positionRider)."""
    if rider.sneaking:
        raise Unmodelled(f"a player getting off {rider.vehicle.type} (where the vehicle puts it down)")
    rider.motion = (0.0, 0.0, 0.0)
    position_rider(rider)


def stop_riding(rider: Entity) -> None:
    if rider.vehicle is not None:
        rider.vehicle.passengers.remove(rider)
        rider.vehicle = None


def summon_with_passengers(store: EntityStore, type_id: str, pos, nbt: Compound | None,
                           dimension: str = OVERWORLD) -> Entity:
    """``summon`` with ``Passengers`` in ``dimension``: the vehicle, then each passenger compound
    (``id`` required) at the same position, depth first, riding it. A passenger that cannot be
    created is skipped."""
    riders = nbt.get("Passengers") if nbt is not None else None
    own = nbt
    if riders is not None:
        own = Compound((k, v) for k, v in nbt.items() if k != "Passengers")
    vehicle = store.summon(type_id, pos, own, dimension=dimension)
    for rider_nbt in riders if isinstance(riders, List) else ():
        kind = rider_nbt.get("id") if isinstance(rider_nbt, Compound) else None
        if not isinstance(kind, String):
            continue
        try:
            rider = summon_with_passengers(store, normalise_id(str(kind)), pos, rider_nbt, dimension)
        except CommandFailure:
            continue
        start_riding(rider, vehicle)
    return vehicle


def _by_uuid_field(store: EntityStore, entity: Entity, key: str) -> list[Entity]:
    value = entity.data.get(key)
    if isinstance(value, IntArray) and len(value) == 4:
        found = store.by_uuid(tuple(int(v) for v in value))
        return [found] if found is not None and found.alive else []
    return []


def related(state, entity: Entity | None, relation: str) -> list[Entity]:
    """The entities ``execute on <relation>`` runs as, from ``entity`` (None: the server)."""
    store = state.entities
    if entity is None:
        return []
    if relation == "passengers":
        return passengers_of(entity)
    if relation == "vehicle":
        vehicle = vehicle_of(entity)
        return [] if vehicle is None else [vehicle]
    if relation == "owner" and entity.type in _OWNABLE:
        return _by_uuid_field(store, entity, "Owner")
    if relation == "origin" and entity.type in _TRACEABLE:
        return _by_uuid_field(store, entity, _TRACEABLE[entity.type])
    if relation in ("target", "attacker") and entity.type == INTERACTION:
        return _interaction_player(store, entity, "interaction" if relation == "target" else "attack")
    if relation == "attacker" and living.is_living(entity.type):
        attacker = combat.last_attacker(state, entity)
        return [] if attacker is None else [attacker]
    if relation == "target" and _is_mob(entity) and not entity.data.get("NoAI"):
        raise Unmodelled(f"execute on target: a {entity.type}'s target comes from its AI, which is not modelled")
    if relation == "controller":
        return _controller(entity)
    if relation == "leasher" and (_is_mob(entity) or entity.type in BOATS) and "leash" in entity.data:
        raise Unmodelled(f"execute on leasher: a {entity.type}'s leash is not modelled")
    return []


def _controller(entity: Entity) -> list[Entity]:
    riders = passengers_of(entity)
    if not riders:
        return []
    if entity.type in BOATS:
        return riders[:1] if living.is_living(riders[0].type) else []
    if _is_mob(entity):
        raise Unmodelled(f"execute on controller: whether a {entity.type} is steered by its rider is not modelled")
    return []


def _is_mob(entity: Entity) -> bool:
    """A Mob (Targeting): a living entity that is neither a player nor an armor stand."""
    return living.is_living(entity.type) and not entity.is_player and entity.type != "minecraft:armor_stand"


def _interaction_player(store: EntityStore, entity: Entity, key: str) -> list[Entity]:
    """Level.getPlayerByUUID of the record's ``player``: a player in the interaction's level."""
    record = entity.data.get(key)
    player = record.get("player") if isinstance(record, Compound) else None
    if not isinstance(player, IntArray) or len(player) != 4:
        return []
    uuid = tuple(int(v) for v in player)
    return [p for p in store.players() if p.alive and p.uuid == uuid and p.dimension == entity.dimension][:1]


def self_and_passengers(entity: Entity) -> list[Entity]:
    found = [entity]
    for p in passengers_of(entity):
        found += self_and_passengers(p)
    return found
