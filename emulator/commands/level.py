"""The commands on the world's level data: ``list``, ``weather``, ``difficulty``, ``seed``,
``defaultgamemode``, ``worldborder``, ``setworldspawn``, ``spawnpoint``, ``spreadplayers``, ``forceload`` and ``stopwatch`` (the
parser keeps them as text, checked against the command tree; each is read again here).

Sources (decompiled 1.21): server/commands/ListPlayersCommand.java (format: the players online),
WeatherCommand.java (setClear/setRain/setThunder -> ServerLevel.setWeatherParameters; the result is
the duration given, -1 without one), DifficultyCommand.java (the query's result is Difficulty.getId;
a set returns 0, or fails ERROR_ALREADY_DIFFICULT), SeedCommand.java ((int) the seed),
DefaultGameModeCommands.java (setMode: the players whose mode the forced game mode changed: none,
no game mode is forced here), WorldBorderCommand.java, SetWorldSpawnCommand.java (setSpawn: outside
the overworld a failure message and result 0), SetSpawnCommand.java (ServerPlayer.setRespawnPosition
with forced true; the result is the number of players), AngleArgument (wrapDegrees, ``~`` from the
execution yaw), BlockPosArgument.getSpawnablePos, ForceLoadCommand.java (changeForceLoad, queryForceLoad,
listForceLoad, removeAll; ServerLevel.setChunkForced answers whether the mark changed).
"""
from __future__ import annotations

import math

import numpy as np

from emulator.world import mth, spreading, stopwatches
from emulator.world.dimensions import OVERWORLD
from emulator.world.entities import in_spawnable_bounds
from emulator.world.errors import CommandFailure
from emulator.world.level_settings import DIFFICULTIES, MAX_BORDER_SIZE
from emulator.world.semantics import wrap32
from emulator.world.weather import RAIN_DELAY, RAIN_DURATION, THUNDER_DURATION
from mcfunction_parser import ast, selectors
from mcfunction_parser.arguments import duration, vec2, vec3
from mcfunction_parser.nbt import Byte, Compound, Float, Int, IntArray, String
from mcfunction_parser.reader import ParseError, Reader

from . import entities

RESPAWN_COMPOUND_VERSION = (1, 21, 5)  # ServerPlayer saves ``respawn`` (RespawnConfig) for SpawnX ...
MAX_BORDER_CENTER = 2.9999984e7


class Words:
    """A generic command's arguments read in order (the command tree already checked them)."""

    def __init__(self, env, cmd: ast.GenericCommand) -> None:
        self.cmd = cmd
        self.reader = Reader(cmd.text, cmd.loc, tuple(env.state.version))
        self.reader.pos = len(cmd.name)
        self.reader.skip_ws()

    def more(self) -> bool:
        return self.reader.more()

    def read(self, parse):
        try:
            value = parse(self.reader)
        except ParseError as error:
            raise CommandFailure("dpemu.command.unreadable", self.cmd.name, error.message, report=True) from None
        self.reader.skip_ws()
        return value

    def word(self) -> str:
        return self.read(Reader.word)


def list_players(env, cmd: ast.GenericCommand, ctx) -> int:
    """``list [uuids]``: the number of players online (PlayerList.getPlayers)."""
    return len(env.state.entities.players())


def weather(env, cmd: ast.GenericCommand, ctx) -> int:
    """``weather clear|rain|thunder [DURATION]``; without a duration one is drawn (clear:
    RAIN_DELAY, rain: RAIN_DURATION, thunder: THUNDER_DURATION) from a random that is not the
    level's (warned)."""
    words = Words(env, cmd)
    kind = words.word()
    given = words.read(lambda r: duration(r, 1)) if words.more() else -1
    state = env.state
    drawn = given
    if given == -1:
        env.warn(cmd, f"'weather {kind}' without a duration draws it from the emulator's random, not the level's")
        drawn = state.weather.sample({"clear": RAIN_DELAY, "rain": RAIN_DURATION, "thunder": THUNDER_DURATION}[kind])
    if kind == "clear":
        state.weather.set(drawn, 0, False, False)
    else:
        state.weather.set(0, drawn, True, kind == "thunder")
    return given


def difficulty(env, cmd: ast.GenericCommand, ctx) -> int:
    settings = env.state.level_settings
    words = Words(env, cmd)
    if not words.more():
        return DIFFICULTIES.index(settings.difficulty)
    wanted = words.word()
    if wanted == settings.difficulty:
        raise CommandFailure("commands.difficulty.failure", wanted)
    settings.difficulty = wanted
    return 0


def seed(env, cmd: ast.GenericCommand, ctx) -> int:
    return wrap32(env.state.random_sequences.world_seed)


def defaultgamemode(env, cmd: ast.GenericCommand, ctx) -> int:
    """The game mode players joining from now on start in; no mode is forced, so none changes."""
    env.state.level_settings.default_gamemode = Words(env, cmd).word()
    return 0


# ---------------------------------------------------------------------- worldborder
def worldborder(env, cmd: ast.GenericCommand, ctx) -> int:
    settings = env.state.level_settings
    words = Words(env, cmd)
    action = words.word()
    if action == "get":  # getSize: Mth.floor(size + 0.5)
        return math.floor(settings.border_size + 0.5)
    if action in ("set", "add"):
        distance = words.read(Reader.double)
        seconds = int(words.word()) if words.more() else 0
        if seconds > 0:
            env.unmodelled(cmd, "a world border moving over time is not modelled: it takes its new size at once")
        return _set_size(settings, distance + (settings.border_size if action == "add" else 0.0))
    if action == "center":
        x = float(np.float32(_coordinate(words.word(), ctx.pos[0])))
        z = float(np.float32(_coordinate(words.word(), ctx.pos[2])))
        if (x, z) == settings.border_center:
            raise CommandFailure("commands.worldborder.center.failed")
        if abs(x) > MAX_BORDER_CENTER or abs(z) > MAX_BORDER_CENTER:
            raise CommandFailure("commands.worldborder.set.failed.far", "2.9999984E7")
        settings.border_center = (x, z)
        return 0
    setting = words.word()
    field, value = _border_field(action, setting, words.word())
    if getattr(settings, field) == value:
        raise CommandFailure(f"commands.worldborder.{action}.{setting}.failed")
    setattr(settings, field, value)
    return int(value)


def _set_size(settings, size: float) -> int:
    """WorldBorderCommand.setSize: the result is (int)(new size - old size)."""
    old = settings.border_size
    if old == size:
        raise CommandFailure("commands.worldborder.set.failed.nochange")
    if size < 1.0:
        raise CommandFailure("commands.worldborder.set.failed.small")
    if size > MAX_BORDER_SIZE:
        raise CommandFailure("commands.worldborder.set.failed.big", "5.9999968E7")
    settings.border_size = size
    return int(size - old)


def _border_field(action: str, setting: str, number: str) -> tuple[str, float]:
    """``damage amount|buffer F`` (floats widened to double) and ``warning time|distance N``."""
    if action == "damage":
        return ("border_damage_per_block" if setting == "amount" else "border_damage_buffer",
                float(np.float32(float(number))))
    return ("border_warning_time" if setting == "time" else "border_warning_blocks", int(number))


def _coordinate(word: str, base: float) -> float:
    """One axis of a Vec2Argument (``~`` relative to the execution position); an absolute integer
    is centred (+0.5)."""
    if word.startswith("~"):
        return base + (float(word[1:]) if len(word) > 1 else 0.0)
    return float(word) + (0.5 if "." not in word else 0.0)


# ---------------------------------------------------------------------- spawn
def _spawn_arguments(env, cmd, words: Words, ctx) -> tuple[tuple[int, int, int], np.float32]:
    """An optional spawnable block position (the execution position's block without one) and an
    optional angle (0 without one): AngleArgument (wrapDegrees, ``~`` from the execution yaw), or
    from 1.21.9 a rotation, whose yaw is kept (its pitch is not modelled: warned)."""
    if not words.more():
        return tuple(math.floor(v) for v in ctx.pos), np.float32(0.0)
    source = entities.world_source(env.state, ctx)
    pos = source.position_of(words.read(lambda r: vec3(r, block=True)), centre=False)
    if not in_spawnable_bounds(pos):
        raise CommandFailure("argument.pos.outofbounds")
    block = tuple(math.floor(v) for v in pos)
    if not words.more():
        return block, np.float32(0.0)
    text = words.word()
    if words.more():
        env.unmodelled(cmd, f"'{cmd.name}' with a rotation keeps its yaw only (the pitch is not modelled)")
    relative = text.startswith("~")
    angle = np.float32(float(text[1:] or 0) if relative else float(text))
    return block, mth.wrap_degrees_f(np.float32(angle + np.float32(ctx.rot[0])) if relative else angle)


def setworldspawn(env, cmd: ast.GenericCommand, ctx) -> int:
    words = Words(env, cmd)
    pos, angle = _spawn_arguments(env, cmd, words, ctx)
    if ctx.dimension != OVERWORLD:  # sendFailure, not an exception: the command succeeds with 0
        return 0
    settings = env.state.level_settings
    settings.spawn, settings.spawn_angle = pos, angle
    return 1


def spawnpoint(env, cmd: ast.GenericCommand, ctx) -> int:
    words = Words(env, cmd)
    state = env.state
    if words.more():
        players = entities.players_found(state, words.read(selectors.target), ctx)
    else:
        player = entities.executor(state, ctx)
        if player is None or not player.is_player:
            raise CommandFailure("permissions.requires.player")
        players = [player]
    pos, angle = _spawn_arguments(env, cmd, words, ctx)
    for player in players:
        set_respawn(state, player, ctx.dimension, pos, angle)
    return len(players)


def set_respawn(state, player, dimension: str, pos, angle: np.float32) -> None:
    """ServerPlayer.setRespawnPosition(dimension, pos, angle, forced=true) as its saved data shows
    it: SpawnX/Y/Z, SpawnAngle, SpawnDimension and SpawnForced, from 1.21.5 one ``respawn``
    compound (RespawnConfig: pos, angle, dimension, forced)."""
    data = player.data
    if tuple(state.version) >= RESPAWN_COMPOUND_VERSION:
        data["respawn"] = Compound(pos=IntArray([Int(v) for v in pos]), angle=Float(angle),
                                   dimension=String(dimension), forced=Byte(1))
        return
    data["SpawnX"], data["SpawnY"], data["SpawnZ"] = (Int(v) for v in pos)
    data["SpawnAngle"] = Float(angle)
    data["SpawnDimension"] = String(dimension)
    data["SpawnForced"] = Byte(1)


def spreadplayers(env, cmd: ast.GenericCommand, ctx) -> int:
    """``spreadplayers CENTER SPREAD MAXRANGE [under MAXHEIGHT] RESPECTTEAMS TARGETS``
    (:mod:`emulator.world.spreading`); the centre is a Vec2Argument (an absolute integer centred),
    MAXHEIGHT the level's top without ``under``."""
    words = Words(env, cmd)
    center = (_coordinate(words.word(), ctx.pos[0]), _coordinate(words.word(), ctx.pos[2]))
    distance, max_range = float(words.word()), float(words.word())
    state = env.state
    start = words.reader.pos
    if words.word() == "under":
        max_height = int(words.word())
    else:
        words.reader.pos = start
        max_height = state.entities.table.levels.build_height(ctx.dimension, state.version)[1]
    respect_teams = words.word() == "true"
    targets = entities.found(state, words.read(selectors.target), ctx)
    return spreading.spread(state, targets, center, distance, max_range, max_height, respect_teams, ctx.dimension)


def stopwatch(env, cmd: ast.GenericCommand, ctx) -> int:
    """``stopwatch create|query|restart|remove ID [SCALE]`` (:mod:`emulator.world.stopwatches`)."""
    words = Words(env, cmd)
    action, stopwatch_id = words.word(), words.word()
    if action == "query":
        return stopwatches.query(env.state, stopwatch_id, float(words.word()) if words.more() else 1.0)
    return {"create": stopwatches.create, "restart": stopwatches.restart, "remove": stopwatches.remove}[action](
        env.state, stopwatch_id)


# ---------------------------------------------------------------------- forceload
MAX_FORCED = 256  # ForceLoadCommand.MAX_CHUNK_LIMIT
_COLUMN_LIMIT = 30_000_000


def forceload(env, cmd: ast.GenericCommand, ctx) -> int:
    """ForceLoadCommand on the context's level: ``add``/``remove FROM [TO]`` mark or unmark the
    chunks of the columns' rectangle (at most 256; the result is how many changed, failing when
    none did), ``remove all`` (0), ``query`` (how many are marked: 0 is a failure message, not a
    failure) and ``query POS`` (1, or a failure). Every chunk is loaded here whether marked or not:
    the marks are what a pack reads back."""
    words = Words(env, cmd)
    action = words.word()
    forced = env.state.forced_chunks.setdefault(ctx.dimension, set())
    if action == "query":
        if not words.more():
            return len(forced)
        chunk = tuple(c >> 4 for c in _column(words, ctx))
        if chunk not in forced:
            raise CommandFailure("commands.forceload.query.failure", f"[{chunk[0]}, {chunk[1]}]", ctx.dimension)
        return 1
    if action == "remove" and words.reader.rest_word() == "all":
        forced.clear()
        return 0
    first = _column(words, ctx)
    second = _column(words, ctx) if words.more() else first
    (x0, x1), (z0, z1) = sorted((first[0], second[0])), sorted((first[1], second[1]))
    if x0 < -_COLUMN_LIMIT or z0 < -_COLUMN_LIMIT or x1 >= _COLUMN_LIMIT or z1 >= _COLUMN_LIMIT:
        raise CommandFailure("argument.pos.outofworld")
    chunks = [(cx, cz) for cx in range((x0 >> 4), (x1 >> 4) + 1) for cz in range((z0 >> 4), (z1 >> 4) + 1)]
    if len(chunks) > MAX_FORCED:
        raise CommandFailure("commands.forceload.toobig", MAX_FORCED, len(chunks))
    add = action == "add"
    changed = [c for c in chunks if (c not in forced) == add]
    if add:
        forced.update(changed)
    else:
        forced.difference_update(changed)
    if not changed:
        raise CommandFailure("commands.forceload.added.failure" if add else "commands.forceload.removed.failure")
    return len(changed)


def _column(words: Words, ctx) -> tuple[int, int]:
    """A ColumnPosArgument: its block column (BlockPos.containing of the source's x and z plus a
    relative offset)."""
    column = words.read(lambda r: vec2(r, integers=True))
    return tuple(math.floor(ctx.pos[axis] + c.value) if c.kind == "rel" else int(c.value)
                 for axis, c in ((0, column.x), (2, column.y)))


GENERIC_HANDLERS = {
    "forceload": forceload,
    "stopwatch": stopwatch,
    "spreadplayers": spreadplayers,
    "list": list_players,
    "weather": weather,
    "difficulty": difficulty,
    "seed": seed,
    "defaultgamemode": defaultgamemode,
    "worldborder": worldborder,
    "setworldspawn": setworldspawn,
    "spawnpoint": spawnpoint,
}
