"""The commands on the world's level data, on both backends: their results, failures and what packs
read afterwards. Sources (decompiled 1.21, server/commands/): ListPlayersCommand.format (the
players online), WeatherCommand.setClear/setRain/setThunder (ServerLevel.setWeatherParameters; the
result is the duration given, -1 without), ServerLevel.advanceWeatherCycle and Level.isRaining /
isThundering (what the weather_check predicate tests: the rain level climbs 0.01 a tick and must
pass 0.2), DifficultyCommand (query: Difficulty.getId; set: 0, ERROR_ALREADY_DIFFICULT),
SeedCommand ((int) seed), DefaultGameModeCommands.setMode (0: no forced game mode),
WorldBorderCommand (getSize: floor(size + 0.5); setSize: (int)(new - old) and its failures;
setCenter 0; damage and warning: the value), SetWorldSpawnCommand.setSpawn (1; 0 outside the
overworld), SetSpawnCommand.setSpawn (the number of players; ServerPlayer.setRespawnPosition as
saved: SpawnX/Y/Z, SpawnAngle, SpawnDimension, SpawnForced; from 1.21.5 ``respawn``),
ForceLoadCommand (changeForceLoad, queryForceLoad, listForceLoad, removeAll)."""
import json

import pytest

from emulator import Emulator
from tests.world.world_emulator import emulator, make_pack


def scores(emu, *holders):
    return [emu.score(h, "o") for h in holders]


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_list_counts_the_players_online(tmp_path, backend):
    emu = emulator(tmp_path, backend, {"t:go": "execute store result score #n o run list\n"
                                               "execute store result score #u o run list uuids"})
    emu.call("t:go")
    assert scores(emu, "#n", "#u") == [0, 0]
    emu.add_player("Alex", (0, 0, 0))
    emu.add_player("Steve", (5, 0, 0))
    emu.call("t:go")
    assert scores(emu, "#n", "#u") == [2, 2]


WEATHER_PACK = {
    "t:rain": "execute store result score #r o run weather rain 600",
    "t:thunder": "execute store result score #t o run weather thunder 10s",
    "t:clear": "execute store result score #c o run weather clear 1d",
    "t:look": "\n".join([
        "execute store success score #raining o if predicate t:raining",
        "execute store success score #thundering o if predicate t:thundering",
        "execute in the_nether store success score #nether o if predicate t:raining",
    ]),
}


def weather_emulator(tmp_path, backend):
    # a #tick function: quiet ticks run in batches on the numba backend, the weather advancing with them
    root = make_pack(tmp_path / "p", {"t:setup": "scoreboard objectives add o dummy", **WEATHER_PACK,
                                      "t:count": "scoreboard players add #ticks o 1"},
                     {"minecraft:tick": ["t:count"]})
    predicates = root / "data" / "t" / "predicate"
    predicates.mkdir(parents=True)
    (predicates / "raining.json").write_text(json.dumps({"condition": "weather_check", "raining": True}))
    (predicates / "thundering.json").write_text(json.dumps({"condition": "weather_check", "thundering": True}))
    emu = Emulator(backend=backend)
    emu.load(root)
    emu.call("t:setup")
    return emu


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_weather_sets_the_level_and_the_predicate_sees_it_as_the_rain_level_rises(tmp_path, backend):
    emu = weather_emulator(tmp_path, backend)
    emu.call("t:rain")
    emu.call("t:look")
    assert scores(emu, "#r", "#raining") == [600, 0]  # the rain level is still 0
    emu.tick(19)  # 19 x 0.01 in float32: 0.19000001
    emu.call("t:look")
    assert scores(emu, "#raining") == [0]
    emu.tick(1)  # 0.20000002 > 0.2
    emu.call("t:look")
    assert scores(emu, "#raining", "#thundering", "#nether") == [1, 0, 0]
    emu.call("t:thunder")
    emu.tick(100)
    emu.call("t:look")
    assert scores(emu, "#t", "#raining", "#thundering") == [200, 1, 1]
    weather = emu.state.weather
    assert (weather.rain_time, weather.thunder_time, weather.raining, weather.thundering) == (100, 100, True, True)
    assert emu.score("#ticks", "o") == 120
    emu.call("t:clear")
    emu.tick(100)
    emu.call("t:look")
    assert scores(emu, "#c", "#raining", "#thundering") == [24000, 0, 0]
    assert emu.state.weather.clear_time == 24000 - 100


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_weather_timers_run_out(tmp_path, backend):
    """advanceWeatherCycle: a rain timer reaching 0 flips the rain off; with doWeatherCycle false
    the timers stand still."""
    emu = weather_emulator(tmp_path, backend)
    emu.call("t:rain")
    emu.tick(599)
    assert emu.state.weather.raining
    emu.tick(1)
    assert not emu.state.weather.raining and emu.state.weather.rain_time == 0


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_difficulty_seed_and_default_game_mode(tmp_path, backend):
    emu = emulator(tmp_path, backend, {"t:go": "\n".join([
        "execute store result score #q o run difficulty",
        "execute store result score #set o run difficulty hard",
        "execute store success score #setok o run difficulty hard",
        "execute store result score #q2 o run difficulty",
        "execute store result score #seed o run seed",
        "execute store result score #dgm o run defaultgamemode creative",
    ])})
    emu.call("t:go")
    assert scores(emu, "#q", "#set", "#setok", "#q2", "#seed", "#dgm") == [2, 0, 0, 3, 0, 0]
    emu.add_player("Alex", (0, 0, 0))
    assert [e for e in emu.state.entities.players()][0].gamemode == "creative"


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_worldborder(tmp_path, backend):
    emu = emulator(tmp_path, backend, {"t:go": "\n".join([
        "execute store result score #get o run worldborder get",
        "execute store result score #set o run worldborder set 100",
        "execute store success score #same o run worldborder set 100",
        "execute store result score #add o run worldborder add -10.6 0",
        "execute store result score #get2 o run worldborder get",
        "execute store success score #small o run worldborder set 0.5",
        "execute store result score #center o run worldborder center 10 20",
        "execute store success score #center2 o run worldborder center 10 20",
        "execute store result score #amount o run worldborder damage amount 3.7",
        "execute store result score #warn o run worldborder warning distance 9",
        "execute store success score #warn2 o run worldborder warning distance 9",
    ])})
    emu.call("t:go")
    assert scores(emu, "#get", "#set", "#same", "#add", "#get2", "#small", "#center", "#center2", "#amount",
                  "#warn", "#warn2") == [59999968, -59999868, 0, -10, 89, 0, 0, 0, 3, 9, 0]
    assert emu.state.level_settings.border_center == (10.5, 20.5)


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_setworldspawn_and_spawnpoint(tmp_path, backend):
    emu = emulator(tmp_path, backend, {"t:go": "\n".join([
        "execute store result score #ws o run setworldspawn 10 64 -3",
        "execute in the_nether store result score #nether o run setworldspawn 1 2 3",
        "execute in the_nether store success score #nether_ok o run setworldspawn 1 2 3",
        "execute store result score #sp o run spawnpoint @a 4 70 5",
        "execute store success score #none o run spawnpoint @a[name=Nobody] 0 0 0",
        "execute store result score #x o run data get entity @p SpawnX",
        "execute store result score #dim o if data entity @p {SpawnDimension:\"minecraft:overworld\",SpawnForced:1b}",
    ])})
    emu.add_player("Alex", (0, 0, 0))
    emu.add_player("Steve", (0, 0, 0))
    emu.call("t:go")
    assert scores(emu, "#ws", "#nether", "#nether_ok", "#sp", "#none", "#x", "#dim") == [1, 0, 1, 2, 0, 4, 1]
    assert emu.state.level_settings.spawn == (10, 64, -3)


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_the_server_runs_its_functions_at_the_world_spawn(tmp_path, backend):
    """MinecraftServer.createCommandSourceStack: Vec3.atLowerCornerOf(the shared spawn), the source of
    the #tick and scheduled functions (ServerFunctionManager.getGameLoopSender)."""
    emu = emulator(tmp_path, backend, {
        "t:go": "setworldspawn 10 64 -3\nschedule function t:later 1t",
        "t:later": "summon marker ~ ~ ~ {Tags:[\"later\"]}",
        "t:tick": "execute unless entity @e[tag=ticked] run summon marker ~ ~ ~ {Tags:[\"ticked\"]}",
    }, {"minecraft:tick": ["t:tick"]})
    emu.call("t:go")
    emu.tick(5)
    positions = {tag: e["pos"] for e in emu.entities() for tag in e["tags"]}
    assert positions == {"later": [10.0, 64.0, -3.0], "ticked": [10.0, 64.0, -3.0]}


def test_spawnpoint_from_1_21_5_saves_one_respawn_compound(tmp_path):
    """ServerPlayer.addAdditionalSaveData from 1.21.5: RespawnConfig under ``respawn`` (pos as an
    int array, angle, dimension, forced) instead of SpawnX/Y/Z ..."""
    emu = emulator(tmp_path, "python", {"t:go": "\n".join([
        "execute in the_nether run spawnpoint @a 4 70 5",
        "execute store result score #y o run data get entity @p respawn.pos[1]",
        "execute store result score #old o if data entity @p SpawnX",
        "execute store result score #dim o if data entity @p "
        "{respawn:{dimension:\"minecraft:the_nether\",forced:1b,angle:0f}}",
    ])}, pack_format=71)
    emu.add_player("Alex", (0, 0, 0))
    emu.call("t:go")
    assert emu.state.version >= (1, 21, 5)
    assert scores(emu, "#y", "#old", "#dim") == [70, 0, 1]


@pytest.mark.parametrize("backend", ["numba", "python"])
def test_forceload_keeps_its_marks_per_level(tmp_path, backend):
    # ForceLoadCommand.changeForceLoad: the chunks whose mark changed (setChunkForced), failing when
    # none did; at most 256 (MAX_CHUNK_LIMIT); query counts the level's marks, query POS fails for
    # an unmarked chunk; remove all returns 0
    emu = emulator(tmp_path, backend, {
        "t:add": "execute store result score #a o run forceload add 0 0 31 15",
        "t:again": "execute store success score #again o run forceload add 5 5",
        "t:count": "execute store result score #n o run forceload query\n"
                   "execute store success score #q o run forceload query 17 3\n"
                   "execute store success score #q2 o run forceload query 40 3\n"
                   "execute in the_nether store result score #nether o run forceload query",
        "t:big": "execute store success score #big o run forceload add 0 0 300 0",
        "t:clear": "execute store result score #r o run forceload remove all\n"
                   "execute store result score #left o run forceload query"})
    emu.call("t:add")
    emu.call("t:again")
    emu.call("t:count")
    assert scores(emu, "#a", "#again", "#n", "#q", "#q2", "#nether") == [2, 0, 2, 1, 0, 0]
    emu.call("t:big")  # 19 chunks in a row: fine; the marks are what changed
    assert scores(emu, "#big") == [1]
    emu.call("t:clear")
    assert scores(emu, "#r", "#left") == [0, 0]


@pytest.mark.parametrize("text,message", [
    ("forceload add 0 0 256 256", "Too many chunks in the specified area (maximum 256, specified 289)"),
    ("forceload query 40 3", "Chunk at [2, 0] in minecraft:overworld is not marked for force loading"),
    ("forceload remove 0 0", "No chunks were removed from force loading"),
    ("forceload add 30000000 0", "That position is out of this world!"),
])
def test_forceload_failures_read_as_the_games(text, message):
    from emulator.commands.dispatch import run_command
    from emulator.commands.entities import new_state
    from emulator.commands.env import Env
    from emulator.world.context import Context
    from emulator.world.errors import CommandFailure
    from mcfunction_parser.diagnostics import Loc
    from mcfunction_parser.parse import parse_command

    cmd, _ = parse_command(text, Loc("t.mcfunction", 1, 1), (1, 21, 4))
    with pytest.raises(CommandFailure) as failure:
        run_command(Env(new_state(), {}, set()), cmd, Context())
    assert failure.value.message == message
