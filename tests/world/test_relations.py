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


@pytest.mark.parametrize("backend", BACKENDS)
def test_on_attacker_is_the_last_living_entity_to_hurt_within_100_ticks(tmp_path, backend):
    # ExecuteCommand ``on attacker``: Attackable.getLastAttacker; LivingEntity.getLastAttacker is
    # getLastHurtByMob, set by hurtServer (setLastHurtByMob) and cleared by baseTick once the
    # attacker is dead or more than 100 ticks passed
    emu = emulator(tmp_path, backend, {
        "t:main": 'summon pig 0 0 0 {Tags:["p"],NoAI:1b}\nsummon zombie 2 0 0 {Tags:["z"],NoAI:1b}\n'
                  'summon skeleton 4 0 0 {Tags:["s"],NoAI:1b}\n'
                  "execute as @e[tag=p] on attacker run scoreboard players add #before o 1\n"
                  "damage @e[tag=p,limit=1] 1 minecraft:mob_attack by @e[tag=z,limit=1]\n"
                  # within the invulnerable ticks only a bigger hurt goes through (LivingEntity.hurt)
                  "damage @e[tag=p,limit=1] 2 minecraft:mob_attack by @e[tag=s,limit=1]",
        "t:who": "execute as @e[tag=p] on attacker run tag @s add attacker",
        "t:clear": "tag @e remove attacker"})
    emu.call("t:main")
    assert emu.score("#before", "o") is None
    emu.call("t:who")
    assert [e["tags"] for e in emu.entities("@e[tag=attacker]")] == [["attacker", "s"]]  # the last one
    emu.call("t:clear")
    emu.tick(100)
    emu.call("t:who")
    assert len(emu.entities("@e[tag=attacker]")) == 1
    emu.call("t:clear")
    emu.tick(1)  # 101 ticks on: forgotten
    emu.call("t:who")
    assert emu.entities("@e[tag=attacker]") == []


@pytest.mark.parametrize("backend", BACKENDS)
def test_on_attacker_forgets_a_dead_attacker_and_an_unangering_hurt(tmp_path, backend):
    emu = emulator(tmp_path, backend, {
        "t:main": 'summon pig 0 0 0 {Tags:["p"],NoAI:1b}\nsummon zombie 2 0 0 {Tags:["z"],NoAI:1b}\n'
                  # mob_attack_no_aggro is in #minecraft:no_anger: no setLastHurtByMob
                  "damage @e[tag=p,limit=1] 1 minecraft:mob_attack_no_aggro by @e[tag=z,limit=1]\n"
                  "execute as @e[tag=p] on attacker run scoreboard players add #calm o 1\n"
                  "damage @e[tag=p,limit=1] 2 minecraft:mob_attack by @e[tag=z,limit=1]\n"
                  "execute as @e[tag=p] on attacker run scoreboard players add #angry o 1\n"
                  "kill @e[tag=z]\n"
                  "execute as @e[tag=p] on attacker run scoreboard players add #dead o 1"})
    emu.call("t:main")
    assert (emu.score("#calm", "o"), emu.score("#angry", "o"), emu.score("#dead", "o")) == (None, 1, None)


@pytest.mark.parametrize("backend", BACKENDS)
def test_on_target_of_a_mob_needs_its_ai(tmp_path, backend):
    # Targeting is Mob and Interaction: a NoAI mob's goals never run, so it has no target; another
    # mob's target comes from its AI, which the emulator does not model (the command fails as not
    # modelled); an armor stand or a marker is no Targeting: nothing
    emu = emulator(tmp_path, backend, {
        "t:calm": 'summon zombie 0 0 0 {Tags:["calm"],NoAI:1b}\nsummon armor_stand 0 0 0 {Tags:["stand"]}\n'
                  "execute as @e[tag=calm] on target run scoreboard players add #calm o 1\n"
                  "execute as @e[tag=stand] on target run scoreboard players add #stand o 1\n"
                  "scoreboard players set #done o 1",
        "t:wild": "summon zombie 0 0 0\nexecute as @e[type=zombie,nbt=!{NoAI:1b}] on target run say found"})
    emu.call("t:calm")
    assert (emu.score("#calm", "o"), emu.score("#stand", "o"), emu.score("#done", "o")) == (None, None, 1)
    assert not any(d.unmodelled for d in emu.diagnostics)
    emu.call("t:wild")
    assert any(d.unmodelled and "target comes from its AI" in d.message for d in emu.diagnostics)


@pytest.mark.parametrize("backend", BACKENDS)
def test_on_controller_and_leasher(tmp_path, backend):
    # Entity.getControllingPassenger: null unless overridden; Boat's is its first passenger when it
    # is a LivingEntity. Leashable (Mob, Boat).getLeashHolder: null without leash data; an entity
    # that is not Leashable gives no context (ExecuteCommand ``on leasher``). A Mob's controller
    # (Mob, Pig, AbstractHorse: AI, saddles, held items) and a leash that is there are not modelled.
    emu = emulator(tmp_path, backend, {
        "t:main": 'summon boat 0 0 0 {Tags:["b"],Passengers:[{id:"minecraft:armor_stand",Tags:["r"]}]}\n'
                  'summon boat 3 0 0 {Tags:["d"],Passengers:[{id:"minecraft:item_display",Tags:["i"]}]}\n'
                  'summon minecart 6 0 0 {Tags:["m"],Passengers:[{id:"minecraft:armor_stand"}]}\n'
                  'summon pig 9 0 0 {Tags:["p"],NoAI:1b}\n'
                  "execute as @e[tag=b] on controller run tag @s add steers\n"
                  "execute as @e[tag=d] on controller run scoreboard players add #display o 1\n"
                  "execute as @e[tag=m] on controller run scoreboard players add #cart o 1\n"
                  "execute as @e[tag=p] on controller run scoreboard players add #pig o 1\n"
                  "execute as @e[tag=p] on leasher run scoreboard players add #leash o 1\n"
                  "execute as @e[tag=m] on leasher run scoreboard players add #cartleash o 1",
        "t:ridden": 'summon pig 0 0 3 {Tags:["q"],Passengers:[{id:"minecraft:zombie"}]}\n'
                    "execute as @e[tag=q] on controller run say found",
        "t:leashed": 'summon pig 0 0 6 {Tags:["l"],leash:[I;1,2,3,4]}\n'
                     "execute as @e[tag=l] on leasher run say found"})
    emu.call("t:main")
    assert [e["tags"] for e in emu.entities("@e[tag=steers]")] == [["r", "steers"]]
    assert [emu.score(h, "o") for h in ("#display", "#cart", "#pig", "#leash", "#cartleash")] == [None] * 5
    assert not any(d.unmodelled for d in emu.diagnostics)
    emu.call("t:ridden")
    assert any(d.unmodelled and "steered by its rider" in d.message for d in emu.diagnostics)
    emu.call("t:leashed")
    assert any(d.unmodelled and "leash is not modelled" in d.message for d in emu.diagnostics)
