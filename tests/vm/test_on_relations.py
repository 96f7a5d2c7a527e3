"""``execute on vehicle|passengers`` in the VM: the entity table keeps each entity's vehicle and
when it got on (EI_VEHICLE, EI_SEAT), so the VM follows the relation as the reference does.

Sources (decompiled 1.21): server/commands/ExecuteCommand.java (on: expandOneToOneEntityRelation
for the vehicle, expandOneToManyEntityRelation for the passengers, in their list's order; only
the executor changes; no executor gives no context), world/entity/Entity.java (getVehicle,
getPassengers: the order they got on).
"""
from __future__ import annotations

import pytest

from tests.vm.helpers import host_kinds, run_both

SETUP = ("scoreboard objectives add o dummy\n"
         'summon armor_stand 0 0 0 {Tags:["v"],Passengers:[{id:"marker",Tags:["p","p1"]},'
         '{id:"armor_stand",Tags:["p","p2"],Passengers:[{id:"marker",Tags:["q"]}]}]}\n'
         'summon marker 3 0 0 {Tags:["lone"]}\n')


@pytest.mark.parametrize("chain, counts", [
    ("as @e[tag=v] on passengers", {"p1": 1, "p2": 1}),
    ("as @e[tag=p] on vehicle", {"v": 2}),
    ("as @e[tag=q] on vehicle on vehicle", {"v": 1}),
    ("as @e on passengers on passengers", {"q": 1}),
    ("as @e[tag=lone] on vehicle", {}),
    ("on passengers", {}),  # the server: no executor
])
def test_on_follows_the_table(tmp_path, chain, counts):
    emu = run_both(tmp_path, SETUP + f"execute {chain} run scoreboard players add @s o 1\n"
                                     f"execute store result score #n o {chain} run tag @s add seen\n")
    found = {t: e["scores"].get("o") for e in emu.entities() for t in e["tags"] if t in ("v", "p1", "p2", "q")}
    assert {t: n for t, n in found.items() if n} == counts
    assert "ExOn" not in host_kinds(emu)


def test_passengers_come_in_the_order_they_got_on(tmp_path):
    # the first passenger gets off and on again: it is the last one now (Entity.addPassenger appends)
    emu = run_both(tmp_path, SETUP + "ride @e[tag=p1,limit=1] dismount\n"
                                     "ride @e[tag=p1,limit=1] mount @e[tag=v,limit=1]\n"
                                     "scoreboard players set #i o 0\n"
                                     "execute as @e[tag=v] on passengers store result score @s o run "
                                     "scoreboard players add #i o 1\n"
                                     "kill @e[tag=p2]\n"
                                     "execute store result score #left o as @e[tag=v] on passengers if entity @s\n")
    order = {t: e["scores"].get("o") for e in emu.entities() for t in e["tags"] if t in ("p1", "p2")}
    assert order == {"p1": 2}  # p2 (killed since) was first
    assert emu.score("#left", "o") == 1
    assert "ExOn" not in host_kinds(emu)
