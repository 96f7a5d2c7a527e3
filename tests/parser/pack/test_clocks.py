"""26.1's world clocks and timelines as the pack loader reads them, and the functions that name one.

Sources (26.1.2, decompiled): world/timeline/Timeline.java (DIRECT_CODEC: clock, period_ticks a
positive int, time_markers id -> ticks or {ticks, show_in_commands}; validateInternal: markers in
[0, period); validateRegistry: a marker once per clock), world/timeline/Timelines.java (the game's
timelines), commands/arguments/ResourceArgument.parse (an unknown clock or timeline fails the line
when the function loads: argument.resource.not_found).
"""
import json

from mcfunction_parser.pack.clocks import OVERWORLD, VANILLA_TIMELINES, Timeline
from mcfunction_parser.pack.loader import load_packs
from tests.parser.pack.packbuild import meta

META_26_1 = {"pack": {"description": "t", "min_format": 101, "max_format": 101}}


def test_a_packs_clocks_and_timelines_join_the_games(make_pack):
    root = make_pack(meta_json=META_26_1, files={
        "data/t/world_clock/season.json": "{}",
        "data/t/timeline/year.json": json.dumps({"clock": "t:season", "period_ticks": 100, "tracks": {},
                                                 "time_markers": {"t:spring": 10, "fall": {"ticks": 60,
                                                                                          "show_in_commands": True}}}),
        "data/minecraft/timeline/day.json": json.dumps({"clock": "overworld", "period_ticks": 1000,
                                                        "time_markers": {"t:dusk": 900}}),
    })
    loaded = load_packs([root])
    assert not loaded.errors and loaded.clocks.clocks == ("minecraft:overworld", "minecraft:the_end", "t:season")
    assert loaded.clocks.timelines["t:year"] == Timeline("t:season", 100, {"t:spring": (10, False),
                                                                           "minecraft:fall": (60, True)})
    assert loaded.clocks.timelines["minecraft:day"] == Timeline(OVERWORLD, 1000, {"t:dusk": (900, False)})
    assert loaded.clocks.markers(OVERWORLD) == {"t:dusk": (900, 1000)}  # the pack's day replaced the game's
    assert loaded.clocks.timelines["minecraft:moon"] == VANILLA_TIMELINES["minecraft:moon"]


def test_timelines_the_game_refuses(make_pack):
    root = make_pack(meta_json=META_26_1, files={
        "data/t/timeline/a.json": json.dumps({"clock": "t:nowhere"}),
        "data/t/timeline/b.json": json.dumps({"clock": "overworld", "period_ticks": 0}),
        "data/t/timeline/c.json": json.dumps({"clock": "overworld", "period_ticks": 10, "time_markers": {"t:x": 10}}),
        "data/t/timeline/d.json": json.dumps({"clock": "overworld", "time_markers": {"noon": 5}}),
    })
    loaded = load_packs([root])
    assert [d.message for d in loaded.errors] == [
        "timeline: unknown world clock 't:nowhere'",
        "timeline: period_ticks must be a positive integer, got 0",
        "timeline: Time Marker t:x must be in range [0; 10)",
        "timeline t:d: time marker minecraft:noon is defined for clock minecraft:overworld already "
        "(by minecraft:day)"]
    assert sorted(loaded.clocks.timelines) == sorted([*VANILLA_TIMELINES, "t:d"])


def test_a_function_naming_an_unknown_clock_or_timeline_does_not_load(make_pack):
    root = make_pack(meta_json=META_26_1, files={
        "data/t/world_clock/season.json": "{}",
        "data/t/function/ok.mcfunction": "time of t:season query time\ntime query day repetition\n",
        "data/t/function/clock.mcfunction": "say hi\nexecute if entity @s run time of t:nope add 5\n",
        "data/t/function/timeline.mcfunction": "return run time of t:season query t:nope\n",
    })
    loaded = load_packs([root])
    assert sorted(loaded.functions) == ["t:ok"] and sorted(loaded.refused) == ["t:clock", "t:timeline"]
    assert [(d.path.rsplit("/", 1)[1], d.line, d.col, d.message) for d in loaded.errors] == [
        ("clock.mcfunction", 2, 34, "Can't find element 't:nope' of type 'minecraft:world_clock'"),
        ("timeline.mcfunction", 1, 35, "Can't find element 't:nope' of type 'minecraft:timeline'")]
    assert loaded.errors[0].format().endswith("^") and loaded.errors[0].source_line.startswith("execute")


def test_releases_before_26_1_read_no_clocks(make_pack):
    root = make_pack(meta_json=meta(94), files={"data/t/world_clock/season.json": "{}"})
    assert load_packs([root]).clocks is None
