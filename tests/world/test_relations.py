"""``execute on``, riding from summon ``Passengers`` and ``ride``, on both backends.

Sources (decompiled 1.21): commands/ExecuteCommand (``on``: only the executor changes; a removed
entity or a missing executor gives no context), world/entity/EntityType.loadEntityRecursive and
ServerLevel.tryAddFreshEntityWithPassengers (vehicle first, then its passengers depth first, each
riding it), world/entity/Entity.startRiding, world/entity/Marker (accepts no passengers),
server/commands/RideCommand (mount/dismount and their failures), OwnableEntity / TraceableEntity
(``Owner`` / ``Thrower`` UUIDs).
"""
from __future__ import annotations

import pytest

from tests.world.world_emulator import emulator

BACKENDS = ["python", "numba"]
CART = ('summon minecart 1 2 3 {Tags:["cart"],Passengers:[{id:"minecraft:pig",Tags:["rider"],'
        'Passengers:[{id:"zombie",Tags:["top"]}]},{id:"minecraft:cow",Tags:["second"]}]}')


@pytest.mark.parametrize("backend", BACKENDS)
def test_summon_passengers_ride_in_creation_order(tmp_path, backend):
    emu = emulator(tmp_path, backend, {"t:main": CART + "\n"
        "execute as @e[tag=cart] on passengers run tag @s add on_cart\n"
        "execute as @e[tag=top] on vehicle on vehicle run tag @s add grandparent\n"
        "execute store result score #n o if entity @e[tag=on_cart]\n"
        "execute as @e[tag=cart] on vehicle run scoreboard players set #cart_rides o 1"})
    emu.call("t:main")
    assert [e["type"] for e in emu.entities("@e")] == [  # depth first
        "minecraft:minecart", "minecraft:pig", "minecraft:zombie", "minecraft:cow"]
    assert [e["tags"] for e in emu.entities("@e[tag=on_cart]")] == [["on_cart", "rider"], ["on_cart", "second"]]
    assert [e["tags"] for e in emu.entities("@e[tag=grandparent]")] == [["cart", "grandparent"]]
    assert emu.score("#n", "o") == 2
    assert emu.score("#cart_rides", "o") is None  # no vehicle: no context
    # every passenger is created at the summon position
    assert {tuple(e["pos"]) for e in emu.entities("@e")} == {(1.5, 2.0, 3.5)}  # centred x and z


@pytest.mark.parametrize("backend", BACKENDS)
def test_on_keeps_the_position_and_skips_killed_riders(tmp_path, backend):
    emu = emulator(tmp_path, backend, {"t:main": CART + "\n"
        "execute positioned 9.25 9 9.25 as @e[tag=cart] on passengers run summon marker ~ ~ ~ {Tags:[\"here\"]}\n"
        "kill @e[tag=second]\n"
        "execute as @e[tag=cart] on passengers run tag @s add left"})
    emu.call("t:main")
    assert [tuple(e["pos"]) for e in emu.entities("@e[tag=here]")] == [(9.25, 9.0, 9.25)] * 2
    assert [e["tags"] for e in emu.entities("@e[tag=left]")] == [["left", "rider"]]


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_marker_takes_no_passengers(tmp_path, backend):
    emu = emulator(tmp_path, backend, {"t:main": 'summon marker 0 0 0 {Tags:["m"],Passengers:[{id:"pig"}]}\n'
                                       "execute as @e[tag=m] on passengers run scoreboard players add #n o 1"})
    emu.call("t:main")
    assert len(emu.entities("@e[type=pig]")) == 1  # spawned, but not riding
    assert emu.score("#n", "o") is None


@pytest.mark.parametrize("backend", BACKENDS)
def test_ride_mount_and_dismount(tmp_path, backend):
    emu = emulator(tmp_path, backend, {"t:main": "\n".join([
        'summon pig 0 0 0 {Tags:["a"]}', 'summon cow 0 0 0 {Tags:["b"]}',
        "execute store success score #mount o run ride @e[tag=a,limit=1] mount @e[tag=b,limit=1]",
        "execute store success score #again o run ride @e[tag=a,limit=1] mount @e[tag=b,limit=1]",  # already riding
        "execute store success score #loop o run ride @e[tag=b,limit=1] mount @e[tag=a,limit=1]",  # a rides b
        "execute as @e[tag=b] on passengers run tag @s add riding",
        "execute store success score #off o run ride @e[tag=a,limit=1] dismount",
        "execute store success score #off2 o run ride @e[tag=a,limit=1] dismount",  # not riding
        "execute store success score #none o run ride @e[tag=nobody,limit=1] dismount",
    ])})
    emu.call("t:main")
    scores = [emu.score(h, "o") for h in ("#mount", "#again", "#loop", "#off", "#off2", "#none")]
    assert scores == [1, 0, 0, 1, 0, 0]
    assert [e["tags"] for e in emu.entities("@e[tag=riding]")] == [["a", "riding"]]


@pytest.mark.parametrize("backend", BACKENDS)
def test_owner_and_origin_follow_uuids(tmp_path, backend):
    emu = emulator(tmp_path, backend, {"t:main": "\n".join([
        'summon pig 0 0 0 {UUID:[I;1,2,3,4],Tags:["boss"]}',
        'summon wolf 0 0 0 {Owner:[I;1,2,3,4],Tags:["dog"]}',
        'summon arrow 0 0 0 {Owner:[I;1,2,3,4],Tags:["shot"]}',
        'summon item 0 0 0 {Thrower:[I;1,2,3,4],Item:{id:"stone",count:1},Tags:["drop"]}',
        'summon pig 0 0 0 {Owner:[I;1,2,3,4],Tags:["wild"]}',  # a pig has no owner relation
        "execute as @e[tag=dog] on owner run scoreboard players add #owner o 1",
        "execute as @e[tag=shot] on origin run scoreboard players add #origin o 1",
        "execute as @e[tag=drop] on origin run scoreboard players add #origin o 1",
        "execute as @e[tag=wild] on owner run scoreboard players add #wild o 1",
        "execute as @e[tag=dog] on origin run scoreboard players add #dog_origin o 1",
        "execute on passengers run scoreboard players add #server o 1",  # no executor
    ])})
    emu.call("t:main")
    assert [emu.score(h, "o") for h in ("#owner", "#origin", "#wild", "#dog_origin", "#server")] == [1, 2, None, None, None]


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_vehicle_saves_its_riders_in_passengers(tmp_path, backend):
    # Entity.saveWithoutId: a vehicle writes Passengers, each rider as saveAsPassenger does (id,
    # then its own saved data and riders); a player has no encode id and is left out; Entity.load
    # does not read Passengers, so merging data into a vehicle keeps its riders
    emu = emulator(tmp_path, backend, {"t:main": CART + "\n"
        "execute store result score #riders o run data get entity @e[tag=cart,limit=1] Passengers\n"
        "execute store result score #top o if data entity @e[tag=cart,limit=1] "
        "Passengers[{id:\"minecraft:pig\"}].Passengers[{id:\"minecraft:zombie\",Tags:[\"top\"]}]\n"
        "execute store result score #match o if entity @e[nbt={Passengers:[{Tags:[\"second\"]}]}]\n"
        "data merge entity @e[tag=cart,limit=1] {Passengers:[],Tags:[\"cart\",\"merged\"]}\n"
        "execute store result score #after o run data get entity @e[tag=merged,limit=1] Passengers\n"
        "execute store result score #none o run data get entity @e[tag=top,limit=1] Passengers\n"
        "summon pig 0 0 0 {Tags:[\"mount\"]}\n"
        "ride @p mount @e[tag=mount,limit=1]\n"
        "execute store success score #player o run data get entity @e[tag=mount,limit=1] Passengers\n"
        "execute as @p on vehicle run scoreboard players set #rides o 1",
    })
    emu.add_player("Steve", (0.0, 0.0, 0.0))
    emu.call("t:main")
    assert emu.score("#riders", "o") == 2  # the pig and the cow (the zombie rides the pig)
    assert emu.score("#top", "o") == 1
    assert emu.score("#match", "o") == 1
    assert emu.score("#after", "o") == 2  # the merge's empty Passengers changed nothing
    assert emu.score("#none", "o") == 0  # no riders: no Passengers (the get fails, storing 0)
    assert emu.score("#rides", "o") == 1 and emu.score("#player", "o") == 0  # it rides, unsaved
