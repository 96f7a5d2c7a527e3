"""PackTest 2 on the game's test framework (1.21.5+): ``@environment`` with test environment files,
``@skyaccess`` and the barriers round a test, ``assert|await entity ... inside`` (misode/packtest
README and AssertCommand; TestEnvironmentDefinition; TestInstanceBlockEntity.encaseStructure)."""
import json
import xml.etree.ElementTree as ET

import pytest

from emulator.testing import discover, run_suite
from emulator.testing.junit import junit_xml
from tests.conftest import write_pack

NEW = 71  # 1.21.5: the first format of the game's own test framework


def suite(tmp_path, files, pack_format=NEW, backend="numba"):
    root = write_pack(tmp_path / "pack", files)
    (root / "pack.mcmeta").write_text(json.dumps({"pack": {"pack_format": pack_format, "description": "t"}}))
    summary = run_suite(discover([root]), backend)
    return summary, {r.id: r for r in summary.results}


ENVIRONMENTS = {
    "demo/test_environment/scored.json": json.dumps({"type": "minecraft:function", "setup": "demo:setup",
                                                     "teardown": "demo:teardown"}),
    "demo/test_environment/slow.json": json.dumps({"type": "game_rules", "int_rules": [
        {"rule": "maxCommandChainLength", "value": 7}], "bool_rules": [{"rule": "doDaylightCycle", "value": False}]}),
    "demo/test_environment/both.json": json.dumps({"type": "all_of", "definitions": [
        "demo:scored", {"type": "time_of_day", "time": 13000}]}),
    "demo/test_environment/rainy.json": json.dumps({"type": "weather", "weather": "rain"}),
    "demo/function/setup.mcfunction": "scoreboard objectives add o dummy\nscoreboard players set #env o 1",
    "demo/function/teardown.mcfunction": "scoreboard players set #env o 2",
}


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_environment_functions_rules_and_time_apply_before_the_test(tmp_path, backend):
    files = {**ENVIRONMENTS,
             "demo/test/setup_ran.mcfunction": "# @environment demo:scored\nassert score #env o matches 1\n",
             "demo/test/rules.mcfunction": "# @environment demo:slow\n"
                                           "execute store result storage t:r v int 1 run gamerule maxCommandChainLength\n"
                                           "assert data storage t:r {v:7}\n",
             "demo/test/nested.mcfunction": "# @environment demo:both\nassert score #env o matches 1\n"
                                            "execute store result score #t o run time query daytime\n"
                                            "assert score #t o matches 13002\n",  # set, then 2 ticks to the start
             "demo/test/default.mcfunction": "# @environment minecraft:default\nsucceed\n"}
    summary, results = suite(tmp_path, files, backend=backend)
    assert {k: r.status for k, r in results.items()} == {
        "demo:setup_ran": "passed", "demo:rules": "passed", "demo:nested": "passed", "demo:default": "passed"}, \
        [r.report() for r in results.values()]


def test_a_weather_environment_sets_the_weather_and_an_unknown_one_fails(tmp_path):
    """TestEnvironmentDefinition.Weather: setWeatherParameters(0, 100000, true, false) for rain; the
    rain level then rises 0.01 a tick (ServerLevel.advanceWeatherCycle), so weather_check sees rain
    once it passes 0.2 (Level.isRaining)."""
    raining = json.dumps({"condition": "minecraft:weather_check", "raining": True})
    files = {**ENVIRONMENTS, "demo/predicate/raining.json": raining,
             "demo/test/wet.mcfunction": "# @environment demo:rainy\nexecute if predicate demo:raining run fail dry\n"
                                         "await predicate demo:raining\n",
             "demo/test/nowhere.mcfunction": "# @environment demo:missing\nsucceed\n"}
    summary, results = suite(tmp_path, files)
    assert results["demo:wet"].status == "passed", results["demo:wet"].report()
    assert results["demo:nowhere"].status == "failed"
    assert "Unknown test environment demo:missing" in results["demo:nowhere"].message
    assert summary.line() == "1 passed, 1 failed"


def test_a_type_newer_than_the_known_releases_is_inconclusive():
    """A type a later release adds (the validator's warning lets it load) is not modelled: said so."""
    from emulator.testing import environments

    class Packs:
        test_environments = {"demo:hard": {"type": "minecraft:difficulty", "difficulty": "hard"}}

    with pytest.raises(environments.EnvironmentError) as raised:
        environments.resolve(Packs(), "demo:hard")
    assert raised.value.unmodelled and "'minecraft:difficulty' is not emulated" in raised.value.message


def teardown_files(rules: dict, rule: str) -> dict:
    return {
        "demo/test_environment/ordered.json": json.dumps({"type": "all_of", "definitions": [
            {"type": "function", "teardown": "demo:one"}, {"type": "function", "teardown": "demo:two"},
            {"type": "game_rules", **rules}, {"type": "weather", "weather": "clear"}]}),
        "demo/function/one.mcfunction": "scoreboard players operation #log o *= #ten o\nscoreboard players add #log o 1",
        "demo/function/two.mcfunction": "scoreboard players operation #log o *= #ten o\nscoreboard players add #log o 2",
        "demo/function/prep.mcfunction": "scoreboard objectives add o dummy\nscoreboard players set #ten o 10\n"
                                         f"gamerule {rule} 5\nweather thunder",
    }


@pytest.mark.parametrize("release, rules, rule, order, after, thundering", [
    # in order; the rule's default; the weather cycle reset
    ("1.21.5", {"int_rules": [{"rule": "randomTickSpeed", "value": 0}]}, "randomTickSpeed", 12, "3", False),
    # reversed; the rule as it was; the weather it found applied again
    ("26.1", {"rules": {"minecraft:random_tick_speed": 0}}, "random_tick_speed", 21, "5", True),
])
def test_teardown_follows_the_release(tmp_path, release, rules, rule, order, after, thundering):
    """AllOf.teardown (1.21.5 - 1.21.11: forEach; 26.1: activations.reversed()), SetGameRules.teardown
    (createRule(): the default; 26.1: the saved GameRuleMap), Weather.teardown (resetWeatherCycle;
    26.1: then the type saved from isThundering/isRaining applied)."""
    from emulator import Emulator
    from emulator.testing import environments

    emu = Emulator(backend="python")
    emu.load([write_pack(tmp_path / "p", teardown_files(rules, rule))], release)
    emu.call("demo:prep")
    emu.tick(100)  # the rain and thunder levels reach 1
    assert emu.state.weather.is_thundering("minecraft:overworld")
    activation = environments.set_up(emu, environments.resolve(emu.packs, "demo:ordered"))
    assert emu.state.gamerules.get(rule) == "0" and not emu.state.weather.thundering
    environments.tear_down(emu, activation)
    assert emu.score("#log", "o") == order
    assert emu.state.gamerules.get(rule) == after
    assert emu.state.weather.thundering is thundering and emu.state.weather.raining is thundering


def test_time_of_day_stays_and_a_clock_time_is_set_back(tmp_path):
    """TimeOfDay (until 26.1) has no teardown; ClockTime (26.1) sets the clock back to its saved ticks."""
    from emulator import Emulator
    from emulator.testing import environments

    old = {"demo/test_environment/noon.json": json.dumps({"type": "time_of_day", "time": 6000})}
    emu = Emulator(backend="python")
    emu.load([write_pack(tmp_path / "old", old)], "1.21.5")
    environments.tear_down(emu, environments.set_up(emu, environments.resolve(emu.packs, "demo:noon")))
    assert emu.state.daytime == 6000
    new = {"demo/test_environment/noon.json": json.dumps({"type": "clock_time", "clock": "minecraft:overworld",
                                                          "time": 6000})}
    emu = Emulator(backend="python")
    new["demo/function/prep.mcfunction"] = "time set 100"
    emu.load([write_pack(tmp_path / "new", new)], "26.1")
    emu.call("demo:prep")
    activation = environments.set_up(emu, environments.resolve(emu.packs, "demo:noon"))
    assert emu.state.daytime == 6000
    environments.tear_down(emu, activation)
    assert emu.state.daytime == 100


def test_each_release_knows_its_own_time_type(tmp_path):
    """26.1 registers clock_time in place of time_of_day (TestEnvironmentDefinition.bootstrap)."""
    from emulator import Emulator

    files = {"demo/test_environment/a.json": json.dumps({"type": "time_of_day", "time": 1}),
             "demo/test_environment/b.json": json.dumps({"type": "clock_time", "clock": "minecraft:overworld",
                                                         "time": 1})}
    for release, refused in (("1.21.5", "b"), ("26.1", "a")):
        emu = Emulator(backend="python")
        emu.load([write_pack(tmp_path / release, files)], release)
        errors = [d.message for d in emu.load_diagnostics if d.severity == "error"]
        assert len(errors) == 1 and f"test environment demo:{refused} fails to load" in errors[0], errors
        assert set(emu.packs.test_environments) == {"demo:a", "demo:b"} - {f"demo:{refused}"}


def test_a_test_is_encased_in_barriers_with_a_ceiling_unless_it_has_sky_access(tmp_path):
    # the default structure is 1x1x1 with its corner at the test origin
    files = {
        "demo/test/closed.mcfunction": "assert block ~1 ~ ~ barrier\nassert block ~ ~ ~-1 barrier\n"
                                       "assert block ~ ~1 ~ barrier\nassert block ~ ~-1 ~ barrier\n"
                                       "assert block ~ ~ ~ air\n",
        "demo/test/open.mcfunction": "# @skyaccess\nassert block ~ ~1 ~ air\nassert block ~-1 ~1 ~ barrier\n",
    }
    _, results = suite(tmp_path, files)
    assert results["demo:closed"].status == "passed", results["demo:closed"].report()
    assert results["demo:open"].status == "passed", results["demo:open"].report()


def test_before_1_21_5_the_encasing_has_no_floor(tmp_path):
    # StructureUtils.encaseStructure: walls from the structure's lowest layer up, the ceiling; under
    # the corner the test's structure block (StructureUtils.prepareTestStructure), no barrier; beside
    # it the command block and stone button to rerun the test by hand
    # (StructureUtils.addCommandBlockAndButtonToStartTest: + (1, 0, -1), then north of it)
    files = {"demo/test/old.mcfunction": "assert block ~ ~-1 ~ structure_block\nassert block ~1 ~ ~ barrier\n"
                                         "assert block ~1 ~-1 ~ air\n"
                                         "assert block ~1 ~-1 ~-1 command_block{Command:\"test runclosest\"}\n"
                                         "assert block ~1 ~-1 ~-2 stone_button[face=wall,facing=north,powered=false]\n"}
    _, results = suite(tmp_path, files, pack_format=48)
    assert results["demo:old"].status == "passed", results["demo:old"].report()


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_entity_inside_finds_only_entities_within_the_test_bounds(tmp_path, backend):
    # the tests run side by side 6 blocks apart: "far" lies north, outside every test's bounds
    body = ('summon marker ~0.5 ~ ~0.5 {Tags:["near"]}\nsummon marker ~ ~ ~-4 {Tags:["far"]}\n'
            "summon marker ~1.9 ~ ~ {Tags:[\"edge\"]}\n")
    files = {
        "demo/test/inside.mcfunction": body + "assert entity @e[tag=near] inside\nassert not entity @e[tag=far] inside\n"
                                              "assert entity @e[tag=far]\nassert entity @e[tag=edge] inside\n",
        "demo/test/outside.mcfunction": body + "assert entity @e[tag=far] inside\n",
        "demo/test/not_inside.mcfunction": body + "assert not entity @e[type=marker] inside\n",
        "demo/test/awaits.mcfunction": 'summon marker ~ ~-20 ~ {Tags:["later"]}\nschedule function demo:later 3t\n'
                                       "await entity @e[tag=later] inside\n",
        "demo/function/later.mcfunction": "execute as @e[tag=later] at @s run tp @s ~ ~20 ~",
    }
    _, results = suite(tmp_path, files, backend=backend)
    assert results["demo:inside"].status == "passed", results["demo:inside"].report()
    assert results["demo:outside"].message == "Expected @e[tag=far] inside test"
    assert results["demo:not_inside"].message == "Did not expect @e[type=marker] inside test, got Marker and 1 more"
    assert results["demo:awaits"].status == "passed", results["demo:awaits"].report()


def test_bad_directive_values_are_errors_of_the_test(tmp_path):
    files = {"demo/test/a.mcfunction": "# @skyaccess maybe\nsucceed\n",
             "demo/test/b.mcfunction": "# @environment Not A Location\nsucceed\n"}
    _, results = suite(tmp_path, files)
    assert results["demo:a"].status == "failed" and "@skyaccess: expected true, false or nothing" in results["demo:a"].message
    assert results["demo:b"].status == "failed" and "@environment: expected a resource location" in results["demo:b"].message


def test_an_entity_inside_check_whose_selector_fails_fails_the_test(tmp_path):
    # @s without an executor: the selector finds nothing; a selector the world refuses fails
    files = {"demo/test/bad.mcfunction": "assert entity @e[limit=0] inside\n"}
    _, results = suite(tmp_path, files)
    assert results["demo:bad"].status == "failed" and "Traceback" not in results["demo:bad"].message


@pytest.mark.parametrize("pack_format,ticks,gametime", [
    # 1.21.5+: the structure, then the environment at the end of the server's first tick
    # (GameTestServer.tickServer -> startTests -> GameTestRunner.runBatch); the test's tick count
    # starts at -2 (GameTestInfo.startExecution(1)) and its body runs when it reaches 0, in the
    # ticker's second tick, after that tick's functions and block ticks (MinecraftServer.tickChildren)
    (NEW, 3, 3),
    # PackTest 1.x (1.21): GameTestInfo.ensureStructureIsPlaced waits 20 ticks and the test starts in
    # the next, before its functions (PackTest's MinecraftServerMixin ticks the ticker first)
    (48, 21, 21),
])
def test_a_test_starts_ticks_after_the_load(tmp_path, pack_format, ticks, gametime):
    files = {
        "demo/function/load.mcfunction": "scoreboard objectives add o dummy\n",
        "demo/function/tick.mcfunction": "scoreboard players add #ticks o 1\n",
        "demo/test/timing.mcfunction": f"assert score #ticks o matches {ticks}\n"
                                       "execute store result score #gt o run time query gametime\n"
                                       f"assert score #gt o matches {gametime}\n",
    }
    root = write_pack(tmp_path / "pack", files, tick=["demo:tick"], load=["demo:load"])
    (root / "pack.mcmeta").write_text(json.dumps({"pack": {"pack_format": pack_format, "description": "t"}}))
    [result] = run_suite(discover([root])).results
    assert result.status == "passed", result.report()


def test_a_command_block_the_environment_sets_has_run_when_the_test_starts(tmp_path):
    # Bookshelf's bs.time: its setup places a repeating command block (auto), whose first block
    # tick (CommandBlockEntity.setAutomatic -> scheduleTick, 1 tick) runs before the test starts
    files = {
        "demo/test_environment/clock.json": json.dumps({"type": "minecraft:function", "setup": "demo:setup"}),
        "demo/function/setup.mcfunction":
            'setblock 5 0 5 repeating_command_block[facing=up]{auto:1b,Command:"help me",TrackOutput:1b}\n',
        "demo/test/clock.mcfunction": "# @environment demo:clock\n"
                                      "assert data block 5 0 5 LastOutput.text\n"
                                      "assert data block 5 0 5 {SuccessCount:1}\n",
    }
    _, results = suite(tmp_path, files)
    assert results["demo:clock"].status == "passed", results["demo:clock"].report()
