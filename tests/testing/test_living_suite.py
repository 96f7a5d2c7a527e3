"""A PackTest suite written as public library suites write theirs (a module per file, ``@dummy``
players, ``await`` on NBT, scores read with ``execute store``), over what the living entities
model: xp, effects counting down, attributes and modifiers, damage, a dummy's attack, a player
joining mid-test. Run through ``dpemu test`` on both backends.

Sources (decompiled 1.21): ExperienceCommand, EffectCommands, AttributeCommand, DamageCommand,
MobEffectInstance.tickServer, Player.attack; misode/packtest DummyCommand."""
import pytest
from click.testing import CliRunner

from emulator.cli import main
from tests.conftest import write_pack

SETUP = "scoreboard objectives add t dummy\n"
SUITE = {
    "demo/function/load.mcfunction": SETUP,
    "demo/test/xp/levels.mcfunction": (
        "# @dummy\n"
        "xp add @s 3 levels\n"
        "assert entity @s[level=3]\n"
        "xp add @s 10 points\n"
        "execute store result score #p t run xp query @s points\n"
        "assert score #p t matches 10\n"
        "assert data entity @s {XpLevel:3,XpTotal:10}\n"),
    "demo/test/effect/expires.mcfunction": (
        "# @dummy\n"
        "effect give @s minecraft:slowness 1 0 true\n"
        "assert data entity @s active_effects[{id:\"minecraft:slowness\",show_particles:0b}]\n"
        "await not data entity @s active_effects[{id:\"minecraft:slowness\"}]\n"
        "effect give @s minecraft:glowing infinite\n"
        "await delay 40\n"
        "assert data entity @s active_effects[{id:\"minecraft:glowing\",duration:-1}]\n"),
    "demo/test/attribute/modifier.mcfunction": (
        "# @dummy\n"
        "attribute @s minecraft:generic.attack_damage modifier add demo:boost 3 add_value\n"
        "execute store result score #d t run attribute @s minecraft:generic.attack_damage get\n"
        "assert score #d t matches 4\n"
        "attribute @s minecraft:generic.attack_damage modifier remove demo:boost\n"
        "execute store result score #d t run attribute @s minecraft:generic.attack_damage get 10\n"
        "assert score #d t matches 10\n"),
    "demo/test/damage/cow.mcfunction": (
        "summon cow ~1 ~ ~ {Tags:[\"target\"],DeathLootTable:\"demo:cow\"}\n"
        "damage @e[tag=target,limit=1] 4 minecraft:magic\n"
        "execute store result score #h t run data get entity @e[tag=target,limit=1] Health\n"
        "assert score #h t matches 6\n"
        "damage @e[tag=target,limit=1] 10 minecraft:out_of_world\n"
        "assert not entity @e[tag=target]\n"
        "assert entity @e[type=item,nbt={Item:{id:\"minecraft:leather\"}}]\n"),  # its DeathLootTable
    "demo/loot_table/cow.json": '{"pools": [{"rolls": 1, "entries": [{"type": "item", "name": "leather"}]}]}',
    "demo/test/dummy/attack.mcfunction": (
        "# @dummy\n"
        "fill ~-1 ~ ~-1 ~2 ~2 ~1 air\n"  # no barrier round the zombie's eyes (it would suffocate: Entity.isInWall)
        "summon zombie ~2 ~ ~ {Tags:[\"mob\"],NoAI:1b}\n"
        "await delay 10\n"
        "dummy @s attack @e[tag=mob,limit=1]\n"
        "assert data entity @e[tag=mob,limit=1] {HurtTime:10s}\n"
        "execute store result score #h t run data get entity @e[tag=mob,limit=1] Health 100\n"
        "assert score #h t matches 1900..1999\n"),
    "demo/test/players/join.mcfunction": (
        "dummy Alex spawn\n"
        "await delay 2\n"
        "dummy Bob spawn\n"
        "execute store result score #n t if entity @a[distance=..3]\n"  # the batch's other dummies are elsewhere
        "assert score #n t matches 2\n"
        "dummy Alex leave\n"
        "assert not entity Alex\n"
        "assert entity Bob\n"),
}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_the_living_suite_passes(tmp_path, backend):
    root = write_pack(tmp_path / "suite", SUITE, load=["demo:load"])
    result = CliRunner().invoke(main, ["test", str(root), "--backend", backend, "--strict"])
    assert result.output.splitlines()[-1] == f"{sum('/test/' in f for f in SUITE)} passed, 0 failed", result.output
    assert result.exit_code == 0
