"""PackTest's ``dummy`` command in emulator.testing: what each modelled action changes that a
datapack can observe, the game's refusals (the test goes on), and the actions the emulator cannot
model (the test fails with the reason). Sources: misode/packtest DummyCommand.java and
PackTestExecutor.java, the game's Player.tick/jumpFromGround, Interaction and PlayerList.respawn."""
import pytest

from emulator.testing import discover, run_suite
from tests.conftest import OPEN_AREA
from emulator.world.players import offline_uuid
from emulator.world.statistics import canonical_criterion
from emulator.world.entities import uuid_string

STATS = ("scoreboard objectives add jumps minecraft.custom:minecraft.jump\n"
         "scoreboard objectives add sneaks custom:sneak_time\n"
         "scoreboard objectives add left minecraft.custom:minecraft.leave_game\n"
         "scoreboard objectives add t dummy\n")


def run(pack, text, backend="numba"):
    [result] = run_suite(discover([pack({"demo/test/t.mcfunction": text})]), backend).results
    return result


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_jump_and_sneak_count_their_statistics(pack, backend):
    result = run(pack, "# @dummy\n" + STATS + (
        "dummy @s jump\ndummy @s jump\n"
        "assert score @s jumps matches 2\n"
        "dummy @s sneak true\n"
        "assert not score @s sneaks matches 0..\n"      # counted by the player's tick, not the key
        "await delay 3\n"
        "assert score @s sneaks matches 3\n"
        "dummy @s sneak false\n"
        "await delay 2\n"
        "assert score @s sneaks matches 3\n"), backend)
    assert result.status == "passed", result.report()


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_spawn_selectslot_respawn_and_leave(pack, backend):
    result = run(pack, STATS + (
        "dummy Alex spawn\n"
        "assert entity @a[name=Alex,x=0,y=1,z=0,distance=..0.001]\n"
        "assert data entity Alex {SelectedItemSlot:0,OnGround:0b}\n"  # Dummy.create: not yet landed
        "dummy Alex selectslot 3\n"
        "assert data entity Alex {SelectedItemSlot:2}\n"
        "tag Alex add kept\n"
        "tp Alex 5 5 5 90 0\n"
        "dummy Alex respawn\n"                             # back at its first spawn, tags kept
        "assert entity @a[name=Alex,tag=kept,x=0,y=1,z=0,distance=..0.001,y_rotation=0]\n"
        "assert data entity Alex {SelectedItemSlot:0}\n"
        "dummy Alex leave\n"
        "assert not entity Alex\n"
        "assert score Alex left matches 1\n"), backend)
    assert result.status == "passed", result.report()


def test_attack_and_use_on_an_interaction_entity_record_the_player_and_time(pack):
    result = run(pack, "# @dummy\n" + STATS + (
        "summon interaction ~2 ~ ~ {Tags:[\"box\"]}\n"
        "await delay 2\n"
        "dummy @s attack @e[tag=box,limit=1]\n"
        "assert data entity @e[tag=box,limit=1] {attack:{timestamp:23L}}\n"  # 1.21: the test starts at game time 21
        "assert not data entity @e[tag=box,limit=1] interaction\n"
        "execute store result score #a t run data get entity @e[tag=box,limit=1] attack.player[0]\n"
        "execute store result score #s t run data get entity @s UUID[0]\n"
        "assert score #a t = #s t\n"
        "await delay 1\n"
        "dummy @s use entity @e[tag=box,limit=1]\n"
        "assert data entity @e[tag=box,limit=1] {interaction:{timestamp:24L},attack:{timestamp:23L}}\n"))
    assert result.status == "passed", result.report()


def test_a_refused_action_fails_only_its_command(pack):
    # PackTestExecutor runs each line as a command: a CommandSyntaxException is the command's failure
    result = run(pack, "# @dummy\ndummy @s sneak true\ndummy @s sneak true\ndummy Nobody jump\nfail \"the end\"\n")
    assert (result.status, result.message, result.line) == ("failed", "the end", 5)
    details = "\n".join(result.details)
    assert "t.mcfunction:3: dummy @s sneak true: Dummy Dummy" in details and "is already sneaking" in details
    assert "t.mcfunction:4: dummy Nobody jump: No dummy was found" in details


def test_spawn_refuses_a_name_in_use_or_no_name(pack):
    result = run(pack, "# @dummy\ndummy Bob spawn\ndummy Bob spawn\ndummy @s spawn\nfail \"the end\"\n")
    details = "\n".join(result.details)
    assert "dummy Bob spawn: Dummy Bob is already logged on" in details
    assert "dummy @s spawn: Cannot spawn dummy without a name" in details


@pytest.mark.parametrize("action, reason", [
    ("use entity @e[type=horse,limit=1]", "using minecraft:horse (its mobInteract is not modelled"),
])
def test_actions_the_emulator_cannot_model_make_the_test_inconclusive(pack, action, reason):
    result = run(pack, f"# @dummy\nsummon horse ~3 ~ ~\nsetblock ~ ~-1 ~ stone\ndummy @s {action}\nsucceed\n")
    assert (result.status, result.line) == ("inconclusive", 4)
    assert f"dummy @s {action}: not modelled: {reason}" in result.message


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_attack_hurts_a_mob_with_the_strength_of_the_swing(pack, backend):
    """Player.attack with an empty hand: attack_damage 1 x (0.2 + 0.8 x strength²), the strength
    (ticks since the last attack or join + 0.5) / 5 ticks at attack speed 4 (getAttackStrengthScale);
    damage_dealt counts the health taken x 10, rounded; the kill counts killed:pig."""
    result = run(pack, (
        "scoreboard objectives add dealt minecraft.custom:minecraft.damage_dealt\n"
        "scoreboard objectives add pigs minecraft.killed:minecraft.pig\n"
        "scoreboard objectives add t dummy\n"
        + OPEN_AREA +
        "dummy Alex spawn\n"
        "summon pig ~1 ~ ~ {Tags:[\"p\"],Health:1.2f,DeathLootTable:\"minecraft:empty\"}\n"
        "dummy Alex attack @e[tag=p,limit=1]\n"            # at once: 0.2 + 0.8 x 0.1² = 0.208
        "assert score Alex dealt matches 2\n"
        "assert data entity @e[tag=p,limit=1] {HurtTime:10s}\n"
        "execute store result score #h t run data get entity @e[tag=p,limit=1] Health 1000\n"
        "assert score #h t matches 992\n"
        "await delay 20\n"                                 # full strength, past the hurt cooldown
        "dummy Alex attack @e[tag=p,limit=1]\n"
        "assert not entity @e[tag=p]\n"
        "assert score Alex pigs matches 1\n"
        "assert score Alex dealt matches 12\n"
        "assert entity @e[type=experience_orb,nbt={Value:1s}]\n"), backend)  # Animal: 1-3 points
    assert result.status == "passed", result.report()


def test_attacking_what_is_not_living_does_nothing(pack):
    assert run(pack, "# @dummy\nsummon marker ~1 ~ ~\ndummy @s attack @e[type=marker,limit=1]\n"
                     "assert entity @e[type=marker]\n").status == "passed"


def test_mining_air_succeeds_without_effect(pack):
    assert run(pack, "# @dummy\ndummy @s mine ~ ~5 ~\nassert block ~ ~5 ~ air\n").status == "passed"


@pytest.mark.parametrize("line, col, message", [
    ("dummy @s fly", 10, "dummy: unknown action 'fly'"),
    ("dummy @s sneak maybe", 16, "dummy sneak: expected true or false, got 'maybe'"),
    ("dummy @s selectslot 10", 21, "dummy selectslot: expected a hotbar slot 1..9, got '10'"),
    ("dummy @s use thing", 14, "dummy use: expected item, block or entity, got 'thing'"),
    ("dummy @s jump high", 15, "expected end of command, got 'high'"),
])
def test_malformed_dummy_lines_are_reported_with_file_line_and_column(pack, line, col, message):
    result = run(pack, f"succeed\n  {line}\n")
    assert result.status == "failed" and result.line == 2
    diagnostic = result.details[0]
    assert f"t.mcfunction:2:{col + 2}: error: {message}" in diagnostic


def test_dummies_have_the_offline_mode_uuid():
    # UUID.nameUUIDFromBytes("OfflinePlayer:Notch"), the well-known offline UUID of that name
    assert uuid_string(offline_uuid("Notch")) == "b50ad385-829d-3141-a216-7e7d7539ba7f"


@pytest.mark.parametrize("written, name", [
    ("minecraft.custom:minecraft.jump", "minecraft.custom:minecraft.jump"),
    ("custom:jump", "minecraft.custom:minecraft.jump"),
    ("minecraft.used:carrot_on_a_stick", "minecraft.used:minecraft.carrot_on_a_stick"),
    ("mined:minecraft.stone", "minecraft.mined:minecraft.stone"),
    ("dummy", "dummy"),
    ("teamkill.red", "teamkill.red"),
    ("other.thing:x", "other.thing:x"),
])
def test_statistic_criteria_are_read_as_the_game_reads_them(written, name):
    # ObjectiveCriteria.byName: type and value are resource locations written with '.' for ':'
    assert canonical_criterion(written) == name
