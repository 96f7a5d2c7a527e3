"""Dimensions: every entity is in a level, and the commands and selectors follow the game's rules
for levels, the same on both backends.

Sources (decompiled 1.21): commands/arguments/selector/EntitySelector.java (findEntities,
findPlayers, isWorldLimited), options/EntitySelectorOptions.java (setWorldLimited,
setIncludesEntities), server/commands/ExecuteCommand.java (at, positioned as, in, summon),
commands/CommandSourceStack.java (withLevel), server/commands/TeleportCommand.java (teleportToPos,
teleportToEntity), commands/arguments/DimensionArgument.java (getDimension).
"""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from emulator.api import Emulator
from tests.backends.programs import write_pack

NETHER, END, OVERWORLD = "minecraft:the_nether", "minecraft:the_end", "minecraft:overworld"
SETUP = "scoreboard objectives add v dummy\nscoreboard objectives add id dummy\n"


def run_both(pack: Path, players=(), entry: str = "t:main") -> Emulator:
    """Run ``entry`` on both backends (``players``: (name, pos, dimension) joining first); they agree
    on scores, entities (with their levels, in the store's order), log and diagnostics."""
    runs = []
    for backend in ("python", "numba"):
        emu = Emulator(backend=backend)
        emu.load(pack)
        for name, pos, dimension in players:
            emu.add_player(name, pos, dimension=dimension)
        emu.runtime.call(entry)
        runs.append(emu)
    ref, vm = runs
    assert vm.scores() == ref.scores()
    assert vm.entities() == ref.entities()
    assert [e.text for e in vm.log] == [e.text for e in ref.log]
    assert [d.format() for d in vm.diagnostics] == [d.format() for d in ref.diagnostics]
    return ref


def pack(tmp_path: Path, main: str, **files: str) -> Path:
    return write_pack(tmp_path / "pack", {"t:main": SETUP + main, **files})


def score(emu: Emulator, holder: str, objective: str = "v"):
    return emu.scores().get(objective, {}).get(holder)


# t:digit appends the executor's id to #seq: the order a selector visits entities in, as digits
DIGIT = {"t:digit": "scoreboard players set #ten v 10\nscoreboard players operation #seq v *= #ten v\n"
                    "scoreboard players operation #seq v += @s id"}


def dims(emu: Emulator, selector: str = "@e") -> list[tuple[str, str]]:
    return [(sorted(e["tags"])[0] if e["tags"] else e["name"], e["dimension"]) for e in emu.entities(selector)]


def test_summon_goes_to_the_context_level(tmp_path):
    # SummonCommand.createEntity: source.getLevel(); `execute summon` the same
    emu = run_both(pack(tmp_path, 'summon marker 0 0 0 {Tags:["o"]}\n'
                                  'execute in minecraft:the_nether run summon marker 0 0 0 {Tags:["n"]}\n'
                                  'execute in minecraft:the_end summon marker run tag @s add e\n'))
    assert dims(emu) == [("o", OVERWORLD), ("n", NETHER), ("e", END)]


def test_unlimited_selectors_visit_every_level_in_level_order(tmp_path):
    # EntitySelector.findEntities without isWorldLimited: every level of getAllLevels() in turn
    # (overworld, nether, end), each level's entities in its own order, whatever the creation order
    main = ('execute in minecraft:the_end run summon marker 0 0 0 {Tags:["x","c1"]}\n'
            'execute in minecraft:the_nether run summon marker 0 0 0 {Tags:["x","c2"]}\n'
            'summon marker 0 0 0 {Tags:["x","c3"]}\n'
            'execute in minecraft:the_nether run summon marker 0 0 0 {Tags:["x","c4"]}\n'
            "scoreboard players set #ten v 10\n"
            + "".join(f"scoreboard players set @e[tag=c{i}] id {i}\n" for i in range(1, 5))
            # the creation numbers of @e[tag=x] in the order it visits them, as digits
            + "execute as @e[tag=x] run function t:digit\n"
            "execute store result score #all v if entity @e[tag=x]\n"
            "execute in minecraft:the_nether store result score #all_from_nether v if entity @e[tag=x]\n")
    emu = run_both(pack(tmp_path, main, **DIGIT))
    assert [d for _, d in dims(emu)] == [OVERWORLD, NETHER, NETHER, END]
    assert score(emu, "#seq") == 3241
    assert score(emu, "#all") == score(emu, "#all_from_nether") == 4


@pytest.mark.parametrize("arg", ["distance=0..", "x=0", "y=0", "z=0", "dx=5", "dy=5", "dz=5", "distance=..100"])
def test_position_arguments_limit_a_selector_to_the_source_level(tmp_path, arg):
    # EntitySelectorOptions: distance, x, y, z, dx, dy, dz call setWorldLimited; findEntities then
    # searches source.getLevel() only
    main = ('summon marker 0 0.5 0 {Tags:["x"]}\n'
            'execute in minecraft:the_nether run summon marker 0 0.5 0 {Tags:["x"]}\n'
            'execute in minecraft:the_nether run summon marker 0 0.5 0 {Tags:["x"]}\n'
            f"execute store result score #over v if entity @e[tag=x,{arg}]\n"
            f"execute in minecraft:the_nether store result score #nether v if entity @e[tag=x,{arg}]\n"
            f"execute in minecraft:the_end store result score #end v if entity @e[tag=x,{arg}]\n"
            f"execute as @e[tag=x,{arg}] run scoreboard players add #as v 1\n"
            f"execute in minecraft:the_nether run tag @e[tag=x,{arg}] add seen\n")
    emu = run_both(pack(tmp_path, main))
    assert (score(emu, "#over"), score(emu, "#nether"), score(emu, "#end"), score(emu, "#as")) == (1, 2, 0, 1)
    assert [d for t, d in dims(emu, "@e[tag=seen]")] == [NETHER, NETHER]


def test_self_is_the_executor_in_any_level(tmp_path):
    # findEntities: the currentEntity branch tests source.getEntity() alone (no level)
    main = ('execute in minecraft:the_nether run summon marker 0 0 0 {Tags:["n"]}\n'
            "execute as @e[tag=n] if entity @s[distance=0..] run scoreboard players set #self v 1\n")
    assert score(run_both(pack(tmp_path, main)), "#self") == 1


def test_at_takes_the_entity_level_and_positioned_as_does_not(tmp_path):
    # ExecuteCommand: at = withLevel(entity.level()).withPosition.withRotation; positioned as =
    # withPosition only; `as` keeps the level
    main = ('execute in minecraft:the_nether run summon marker 3 4 5 {Tags:["n"]}\n'
            "execute at @e[tag=n] if dimension minecraft:the_nether run scoreboard players set #at v 1\n"
            "execute positioned as @e[tag=n] if dimension minecraft:overworld run scoreboard players set #pos v 1\n"
            "execute as @e[tag=n] if dimension minecraft:overworld run scoreboard players set #as v 1\n"
            "execute at @e[tag=n] store result score #x v run data get entity @e[tag=n,distance=..1,limit=1] Pos[0]\n")
    emu = run_both(pack(tmp_path, main))
    assert (score(emu, "#at"), score(emu, "#pos"), score(emu, "#as"), score(emu, "#x")) == (1, 1, 1, 3)


def test_tp_to_a_position_goes_to_the_source_level(tmp_path):
    # TeleportCommand.teleportToPos: source.getLevel(); a teleport into another level puts the
    # entity last in that level's order. `execute as E run tp @s ...` runs in the server's level
    # (the overworld): an entity in the nether comes to the overworld, as in the game.
    main = ('summon marker 0 0 0 {Tags:["a"]}\n'
            'summon marker 0 0 0 {Tags:["b"]}\n'
            'execute in minecraft:the_nether run summon marker 0 0 0 {Tags:["c"]}\n'
            "execute in minecraft:the_nether run tp @e[tag=a] 1 2 3\n"
            "execute as @e[tag=b] in minecraft:the_end run tp @s ~ ~ ~\n"
            "execute in minecraft:the_end as @e[tag=b] run tp @s ~1 ~ ~\n"
            'execute in minecraft:the_nether run summon marker 0 0 0 {Tags:["d"]}\n'
            'execute in minecraft:the_nether run summon marker 0 0 0 {Tags:["e"]}\n'
            "execute as @e[tag=e] run tp @s 5 5 5\n")
    emu = run_both(pack(tmp_path, main))
    assert dims(emu) == [("e", OVERWORLD), ("c", NETHER), ("a", NETHER), ("d", NETHER), ("b", END)]
    assert emu.entities("@e[tag=a]")[0]["pos"] == [1.5, 2.0, 3.5]


def test_tp_to_an_entity_goes_to_its_level(tmp_path):
    # TeleportCommand.teleportToEntity: (ServerLevel) destination.level()
    main = ('summon marker 0 0 0 {Tags:["a"]}\n'
            'execute in minecraft:the_end run summon marker 7 8 9 {Tags:["b"]}\n'
            "tp @e[tag=a] @e[tag=b,limit=1]\n"
            "execute as @e[tag=a] at @s if dimension minecraft:the_end run scoreboard players set #end v 1\n")
    emu = run_both(pack(tmp_path, main))
    assert dims(emu) == [("a", END), ("b", END)] or dims(emu) == [("b", END), ("a", END)]
    assert [t for t, _ in dims(emu)] == ["b", "a"]
    assert score(emu, "#end") == 1


def test_tp_within_the_level_stays_in_the_vm(tmp_path):
    # a teleport inside the context's level is jitted; only a crossing one is served by the host
    emu = Emulator(backend="numba")
    emu.load(pack(tmp_path, 'summon marker 0 0 0 {Tags:["a"]}\n'
                            "execute as @e[tag=a] at @s run tp @s ~1 ~ ~\n"
                            "execute in minecraft:the_nether as @e[tag=a] run tp @s ~ ~ ~\n"))
    emu.runtime.call("t:main")
    teleports = [(run.node.loc.line, run.runs) for run in emu.runtime.backend.host_ops_run()
                 if type(run.node).__name__ == "Teleport"]
    assert teleports == [(5, 1)]  # the crossing one, line 5 after SETUP's two
    assert dims(emu) == [("a", NETHER)]


def test_players_are_found_in_join_order_unless_limited_to_a_level(tmp_path):
    # findPlayers: not world limited, the player list (join order) whatever their level; limited,
    # source.getLevel().getPlayers(); an @e over players (it includes entities) visits levels in
    # order. `type=player`, like @a, makes the selector search players (setIncludesEntities(false)).
    main = ("scoreboard players set A id 1\nscoreboard players set B id 2\nscoreboard players set C id 3\n"
            "execute as @a run function t:digit\n"
            "scoreboard players operation #a v = #seq v\nscoreboard players set #seq v 0\n"
            "execute as @e[type=player] run function t:digit\n"
            "scoreboard players operation #typed v = #seq v\nscoreboard players set #seq v 0\n"
            "execute as @e[type=!marker] run function t:digit\n"
            "scoreboard players operation #e v = #seq v\nscoreboard players set #seq v 0\n"
            "execute in minecraft:the_nether as @a[distance=0..] run function t:digit\n"
            "scoreboard players operation #lim v = #seq v\n"
            "execute as @a[limit=1] run scoreboard players operation #first v = @s id\n")
    players = (("A", (0, 0, 0), NETHER), ("B", (0, 0, 0), OVERWORLD), ("C", (0, 0, 0), NETHER))
    emu = run_both(pack(tmp_path, main, **DIGIT), players)
    assert (score(emu, "#a"), score(emu, "#typed"), score(emu, "#first")) == (123, 123, 1)
    assert score(emu, "#e") == 213  # the overworld's B, then the nether's A and C
    assert score(emu, "#lim") == 13


def test_nearest_player_is_searched_in_every_level(tmp_path):
    # @p is not world limited (EntitySelectorParser.parseSelector sets no level limit): the
    # nearest by numeric distance, whichever level it is in; `distance=` limits it to the source's
    main = ("scoreboard players set Near id 1\nscoreboard players set Far id 2\n"
            "execute as @p run scoreboard players operation #p v = @s id\n"
            "execute as @p[distance=0..] run scoreboard players operation #limited v = @s id\n"
            "execute as @n[type=player] run scoreboard players operation #n v = @s id\n")
    players = (("Far", (5, 0, 0), OVERWORLD), ("Near", (1, 0, 0), NETHER))
    emu = run_both(pack(tmp_path, main), players)
    assert (score(emu, "#p"), score(emu, "#limited"), score(emu, "#n")) == (1, 2, 1)


def test_player_dimension_nbt(tmp_path):
    # ServerPlayer.addAdditionalSaveData writes Dimension
    main = ('execute if entity @a[name=N,nbt={Dimension:"minecraft:the_nether"}] run scoreboard players set #n v 1\n'
            'execute if entity @a[name=O,nbt={Dimension:"minecraft:overworld"}] run scoreboard players set #o v 1\n')
    emu = run_both(pack(tmp_path, main), (("N", (0, 0, 0), NETHER), ("O", (0, 0, 0), OVERWORLD)))
    assert (score(emu, "#n"), score(emu, "#o")) == (1, 1)


def test_an_unknown_dimension_fails_the_command(tmp_path):
    # DimensionArgument.getDimension: "Unknown dimension" for `in` and `if dimension`
    main = ("execute in t:nowhere run scoreboard players set #in v 1\n"
            "execute unless dimension t:nowhere run scoreboard players set #unless v 1\n"
            "scoreboard players set #unless_ok v 7\n"
            "execute store success score #unless_ok v unless dimension t:nowhere\n"
            "execute store success score #ok v unless dimension minecraft:the_end\n")
    emu = run_both(pack(tmp_path, main))
    assert (score(emu, "#in"), score(emu, "#unless")) == (None, None)
    assert (score(emu, "#unless_ok"), score(emu, "#ok")) == (0, 1)


FLAT = {"type": "minecraft:flat", "settings": {"layers": [], "biome": "minecraft:plains"}}


def test_custom_dimensions_from_the_pack(tmp_path):
    # data/<ns>/dimension/ declares levels; its dimension type's coordinate_scale scales `in`
    # (CommandSourceStack.withLevel: x * from / to)
    root = pack(tmp_path, "execute positioned 8 0 16 in t:deep run summon marker ~ ~ ~ {Tags:[\"d\"]}\n"
                          "execute in t:flat if dimension t:flat run scoreboard players set #flat v 1\n")
    for name, body in (("dimension/deep", {"type": "t:deep_type", "generator": FLAT}),
                       ("dimension_type/deep_type", {"coordinate_scale": 4.0}),
                       ("dimension/flat", {"type": "minecraft:overworld", "generator": FLAT})):
        (root / "data/t" / f"{name}.json").parent.mkdir(parents=True, exist_ok=True)
        (root / "data/t" / f"{name}.json").write_text(json.dumps(body))
    emu = run_both(root)
    [deep] = emu.entities("@e[tag=d]")
    assert (deep["dimension"], deep["pos"]) == ("t:deep", [8.5 / 4, 0.0, 16.5 / 4])  # positioned centres x/z
    assert score(emu, "#flat") == 1


def test_blocks_are_per_level(tmp_path):
    # SetBlockCommand, FillCommand, ExecuteCommand (if block), BlockDataAccessor: source.getLevel()
    main = ("setblock 0 0 0 stone\n"
            "execute in minecraft:the_nether run setblock 0 0 0 dirt\n"
            "execute in minecraft:the_nether run fill 1 0 0 2 0 0 gold_block\n"
            "execute in minecraft:the_nether run setblock 3 0 0 chest\n"
            "execute if block 0 0 0 stone run scoreboard players set #over v 1\n"
            "execute in minecraft:the_nether if block 0 0 0 dirt run scoreboard players set #nether v 1\n"
            "execute in minecraft:the_end if block 0 0 0 air run scoreboard players set #end v 1\n"
            "execute if block 1 0 0 air in minecraft:the_nether if block 2 0 0 gold_block run "
            "scoreboard players set #fill v 1\n"
            "execute store success score #here v run data get block 3 0 0\n"
            "execute in minecraft:the_nether store success score #there v run data get block 3 0 0\n"
            'execute in minecraft:the_nether run summon marker 0 0 0 {Tags:["n"]}\n'
            "execute as @e[tag=n] at @s if block ~ ~ ~ dirt run scoreboard players set #at v 1\n")
    emu = run_both(pack(tmp_path, main))
    assert [score(emu, h) for h in ("#over", "#nether", "#end", "#fill", "#here", "#there", "#at")] == [1, 1, 1, 1, 0, 1, 1]


def test_location_predicates_read_the_level(tmp_path):
    # LocationPredicate.matches: dimension == the loot context's level: the source's for `execute
    # if predicate`, the entity's own for a selector's `predicate=` (EntitySelectorOptions builds
    # the LootParams on entity.level())
    root = pack(tmp_path, 'execute in minecraft:the_nether run summon marker 0 0 0 {Tags:["n"]}\n'
                          'summon marker 0 0 0 {Tags:["o"]}\n'
                          "execute in minecraft:the_nether if predicate t:nether run scoreboard players set #in v 1\n"
                          "execute if predicate t:nether run scoreboard players set #out v 1\n"
                          "execute as @e[predicate=t:nether] run tag @s add hot\n")
    (root / "data/t/predicate").mkdir(parents=True)
    (root / "data/t/predicate/nether.json").write_text(json.dumps(
        {"condition": "minecraft:location_check", "predicate": {"dimension": "minecraft:the_nether"}}))
    emu = run_both(root)
    assert (score(emu, "#in"), score(emu, "#out")) == (1, None)
    assert [t for t, _ in dims(emu, "@e[tag=hot]")] == ["hot"] and dims(emu, "@e[tag=hot]")[0][1] == NETHER


def test_a_player_changing_level_fires_changed_dimension(tmp_path):
    # ServerPlayer.triggerDimensionChangeTriggers -> ChangeDimensionTrigger (from, to; a missing
    # one matches any)
    root = pack(tmp_path, "execute in minecraft:the_nether run tp @a ~ ~ ~\n")
    for name, conditions in (("any", {}), ("to_nether", {"to": NETHER}), ("to_end", {"to": END}),
                             ("from_over", {"from": OVERWORLD, "to": NETHER})):
        (root / "data/t/advancement").mkdir(parents=True, exist_ok=True)
        (root / "data/t/advancement" / f"{name}.json").write_text(json.dumps(
            {"criteria": {"c": {"trigger": "minecraft:changed_dimension", "conditions": conditions}}}))
    emu = run_both(root, (("A", (0, 0, 0), OVERWORLD),))
    done = {name for name in ("any", "to_nether", "to_end", "from_over")
            if emu.state.advancement_progress.of(emu.state.entities.players()[0], f"t:{name}")}
    assert done == {"any", "to_nether", "from_over"}


def test_a_killed_executor_teleported_to_another_level_stays_out_of_the_world(tmp_path):
    # the context keeps the killed entity (@s); a teleport cannot bring it back into a level
    main = ('summon marker 0 0 0 {Tags:["k"]}\n'
            "execute as @e[tag=k] run function t:gone\n"
            "execute store result score #left v if entity @e[tag=k]\n")
    emu = run_both(pack(tmp_path, main, **{"t:gone": "kill @s\nexecute in minecraft:the_nether run tp @s ~ ~ ~"}))
    assert score(emu, "#left") == 0 and emu.diagnostics == []


RIDE = ('summon pig 0 0 0 {Tags:["v"],Rotation:[10f,0f],Passengers:[{id:"minecraft:marker",Tags:["r"]}]}\n'
        'tp @e[tag=r] 0.25 1 0 30 0\n'
        'summon armor_stand 0 0 0 {Tags:["seat"]}\n'
        'ride @e[tag=v,limit=1] mount @e[tag=seat,limit=1]\n'
        "execute in minecraft:the_nether run tp @e[tag=v] 10 20 30 40 0\n"
        "execute as @e[tag=r] on vehicle if entity @s[tag=v] run scoreboard players set #rides v 1\n"
        "execute as @e[tag=v] on vehicle run scoreboard players set #seated v 1\n")


def test_a_vehicle_crossing_levels_takes_its_passengers_along_from_1_21_2(tmp_path):
    # Entity.teleport: not as a passenger it leaves its vehicle (stopRiding); teleportCrossDimension:
    # each passenger keeps its offset and its turn relative to the vehicle
    # (calculatePassengerTransition) and rides it again in the new level
    emu = run_both(write_pack(tmp_path / "pack", {"t:main": SETUP + RIDE}, pack_format=61))
    assert sorted(dims(emu)) == [("r", NETHER), ("seat", OVERWORLD), ("v", NETHER)]
    assert (score(emu, "#rides"), score(emu, "#seated")) == (1, None)
    rider = emu.entities("@e[tag=r]")[0]
    assert rider["pos"] == [10.25, 21.0, 30.5] and rider["rotation"][0] == 60.0  # the pig at 10.5 20 30.5


def test_before_1_21_2_a_vehicle_crossing_levels_leaves_its_passengers(tmp_path):
    # 1.20 Entity.teleportTo(ServerLevel, ...) into another level: unRide (ejectPassengers, stopRiding)
    emu = run_both(write_pack(tmp_path / "pack", {"t:main": SETUP + RIDE}, pack_format=48))
    assert sorted(dims(emu)) == [("r", OVERWORLD), ("seat", OVERWORLD), ("v", NETHER)]
    assert (score(emu, "#rides"), score(emu, "#seated")) == (None, None)
