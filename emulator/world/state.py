"""The world state that both backends (numba VM and Python reference) act on.

One :class:`WorldState` holds everything a run changes: the scoreboard, the schedule queue,
gamerules, gametime, the log, runtime diagnostics, overflow reports (:mod:`emulator.world.records`)
and NBT storage. Backends mutate it in place; the runtime (:mod:`emulator.runtime.server`) owns the
tick loop. Commands run in a :class:`~emulator.world.context.Context`.

Scoreboard layout (what the VM reads directly)
- Holders and objectives are interned: a name gets a dense id once and keeps it for the run.
  Interning never creates a score and never creates an objective.
- ``values[h, o]`` is an ``int32`` matrix and ``present[h, o]`` a ``uint8`` mask (1 = the score
  is set). An unset score has ``present == 0``; its ``values`` cell is meaningless.
- ``locked[h, o]`` (``uint8``, same shape and growth as ``present``) is the trigger lock of the
  score (Score.locked; 1 = locked). The game creates every score locked, so the invariant is
  ``locked == 1`` wherever ``present == 0``: whoever clears ``present`` sets ``locked`` back to 1.
  ``scoreboard players enable`` creates missing scores (0) and clears their ``locked``;
  ``trigger`` fails unless the score is present and unlocked, then locks it again.
- ``alive[o]`` (``uint8``) says whether objective ``o`` currently exists (``scoreboard objectives
  add`` sets it, ``remove`` clears it and its column). Commands naming an objective that is not
  alive fail ("Unknown scoreboard objective"). ``writable[o]`` (``uint8``, same growth) is 1 when
  ``o`` exists and its criterion is not read-only (what ``set``/``add``/``remove``/``operation``
  may write): the VM reads it in the same test as ``alive``. ``trigger[o]`` is 1 when ``o``'s
  criterion is ``trigger`` (what ``enable`` needs).
- The arrays have spare capacity; interning past it reallocates them (``values``/``present``/
  ``alive``/``writable`` are then new arrays, so re-read the attributes after interning).

Holder names are what the game uses: player and fake-player names (``#x``, ``$y``) as written,
entities by their UUID string.
"""
from __future__ import annotations

import heapq
import itertools
import random
import weakref
from dataclasses import dataclass, field

import numpy as np

from emulator.world.pack_repository import PackRepository
from emulator.world.biomes import BiomeCells
from emulator.world.blocks import WORLD_RELEASE, BlockMap
from emulator.world.advancement_progress import Progress
from emulator.world.bossbars import BossBars
from emulator.world.entities import EntityStore
from emulator.world.hash_order import OpenHashKeys
from emulator.world import furnaces, light
from emulator.world.level_settings import LevelSettings
from emulator.world.block_ticks import BlockTicks
from emulator.world.random_sequences import RandomSequences
from emulator.world.records import Frame, LogEntry, Overflow, RuntimeDiagnostic
from emulator.world.resources import Resources
from emulator.world.weather import Weather
from emulator.world.storage import StorageData
from emulator.world.teams import Teams
from mcfunction_parser.diagnostics import Loc

# Criteria whose scores only the game sets (ObjectiveCriteria with readOnly=true).
READ_ONLY_CRITERIA = frozenset({"health", "food", "air", "armor", "xp", "level"})

_INITIAL_HOLDERS = 64
_INITIAL_OBJECTIVES = 16


class Scoreboard:
    """Interned holders x objectives, int32 values plus a present mask."""

    def __init__(self) -> None:
        self.holders: list[str] = []
        self.holder_ids: dict[str, int] = {}
        self.objectives: list[str] = []
        self.objective_ids: dict[str, int] = {}
        self.criteria: list[str] = []
        self.statistic_ids: set[int] = set()  # objectives whose criterion is a statistic (``type:stat``)
        self.display_names: list[str | None] = []
        self.values = np.zeros((_INITIAL_HOLDERS, _INITIAL_OBJECTIVES), dtype=np.int32)
        self.present = np.zeros((_INITIAL_HOLDERS, _INITIAL_OBJECTIVES), dtype=np.uint8)
        self.locked = np.ones((_INITIAL_HOLDERS, _INITIAL_OBJECTIVES), dtype=np.uint8)
        self.alive = np.zeros(_INITIAL_OBJECTIVES, dtype=np.uint8)
        self.writable = np.zeros(_INITIAL_OBJECTIVES, dtype=np.uint8)
        self.trigger = np.zeros(_INITIAL_OBJECTIVES, dtype=np.uint8)
        # the game's holder map (Scoreboard.playerScores) for the order of ``*``: see tracked_holders
        self.tracked = OpenHashKeys(16, 0.5)
        # per holder: 1 when it is tracked without a score (its last one went with its objective). What `*`
        # names is the holders with a score or this flag (the VM reads it; tracked_holders orders them)
        self.kept = np.zeros(_INITIAL_HOLDERS, dtype=np.uint8)

    # ------------------------------------------------------------------ interning
    def holder_id(self, name: str) -> int:
        """The id of holder ``name``, interning it (and growing the arrays) if new."""
        hid = self.holder_ids.get(name)
        if hid is None:
            hid = len(self.holders)
            self.holders.append(name)
            self.holder_ids[name] = hid
            self._ensure_capacity(hid + 1, len(self.objectives))
        return hid

    def objective_id(self, name: str) -> int:
        """The id of objective ``name``, interning it if new. Interning does not make it exist."""
        oid = self.objective_ids.get(name)
        if oid is None:
            oid = len(self.objectives)
            self.objectives.append(name)
            self.objective_ids[name] = oid
            self.criteria.append("dummy")
            self.display_names.append(None)
            self._ensure_capacity(len(self.holders), oid + 1)
        return oid

    def _ensure_capacity(self, n_holders: int, n_objectives: int) -> None:
        cap_h, cap_o = self.values.shape
        if n_holders <= cap_h and n_objectives <= cap_o:
            return
        new_h = max(cap_h, _grow(cap_h, n_holders))
        new_o = max(cap_o, _grow(cap_o, n_objectives))
        values = np.zeros((new_h, new_o), dtype=np.int32)
        present = np.zeros((new_h, new_o), dtype=np.uint8)
        values[:cap_h, :cap_o] = self.values
        present[:cap_h, :cap_o] = self.present
        locked = np.ones((new_h, new_o), dtype=np.uint8)
        locked[:cap_h, :cap_o] = self.locked
        kept = np.zeros(new_h, dtype=np.uint8)
        kept[:cap_h] = self.kept
        self.kept = kept
        alive = np.zeros(new_o, dtype=np.uint8)
        alive[:cap_o] = self.alive
        writable = np.zeros(new_o, dtype=np.uint8)
        writable[:cap_o] = self.writable
        trigger = np.zeros(new_o, dtype=np.uint8)
        trigger[:cap_o] = self.trigger
        self.values, self.present, self.locked, self.alive = values, present, locked, alive
        self.writable, self.trigger = writable, trigger

    def intern_names_of(self, other: "Scoreboard") -> None:
        """Intern ``other``'s holder and objective names, in its order, into this empty scoreboard:
        a program compiled against ``other`` (which holds those ids) runs on this one."""
        if self.holders or self.objectives:
            raise ValueError("names are interned into an empty scoreboard only")
        for name in other.holders:
            self.holder_id(name)
        for name in other.objectives:
            self.objective_id(name)

    # ------------------------------------------------------------------ objectives
    def exists(self, objective: str) -> bool:
        oid = self.objective_ids.get(objective)
        return oid is not None and bool(self.alive[oid])

    def add_objective(self, name: str, criterion: str = "dummy", display_name: str | None = None) -> bool:
        """``scoreboard objectives add``; False (command fails) when it already exists."""
        oid = self.objective_id(name)
        if self.alive[oid]:
            return False
        self.alive[oid] = 1
        self.writable[oid] = criterion not in READ_ONLY_CRITERIA
        self.trigger[oid] = criterion == "trigger"
        self.criteria[oid] = criterion
        if ":" in criterion:
            self.statistic_ids.add(oid)
        else:
            self.statistic_ids.discard(oid)
        self.display_names[oid] = display_name
        self.present[:, oid] = 0
        self.locked[:, oid] = 1
        return True

    def remove_objective(self, name: str) -> bool:
        """``scoreboard objectives remove``; drops every score; False when it does not exist."""
        if not self.exists(name):
            return False
        oid = self.objective_ids[name]
        self.tracked_holders()  # the map brought up to date first: the holders the VM gave scores are in it
        n = len(self.holders)
        had = np.flatnonzero(self.present[:n, oid])
        self.alive[oid] = 0
        self.writable[oid] = 0
        self.present[:, oid] = 0
        self.locked[:, oid] = 1
        # Scoreboard.removeObjective empties PlayerScores but keeps the holders in the map
        self.kept[had[~self.present[had].any(axis=1)]] = 1
        return True

    def is_writable(self, objective: str) -> bool:
        """False for read-only criteria (``health`` ...): set/add/operation on them fail."""
        return self.criteria[self.objective_ids[objective]] not in READ_ONLY_CRITERIA

    # ------------------------------------------------------------------ scores
    def get(self, holder: str, objective: str) -> int | None:
        """The score, or None when unset (or the holder/objective is unknown)."""
        hid = self.holder_ids.get(holder)
        oid = self.objective_ids.get(objective)
        if hid is None or oid is None or not self.alive[oid] or not self.present[hid, oid]:
            return None
        return int(self.values[hid, oid])

    def block(self, holders, objectives) -> np.ndarray:
        """The scores of many holders on many objectives at once, int64 [holder, objective]; 0
        where unset (the holder or objective unknown, or no score)."""
        hids = np.array([self.holder_ids.get(h, -1) for h in holders], np.int64)
        oids = np.array([self.objective_ids.get(o, -1) for o in objectives], np.int64)
        rows, cols = np.maximum(hids, 0)[:, None], np.maximum(oids, 0)
        known = (hids >= 0)[:, None] & ((oids >= 0) & (self.alive[cols] != 0)) & (self.present[rows, cols] != 0)
        return np.where(known, self.values[rows, cols], 0).astype(np.int64)

    def reader(self, holders, objectives) -> "ScoreReader":
        """A reader of ``block(holders, objectives)`` for reading again and again (each tick)."""
        return ScoreReader(self, list(holders), list(objectives))

    def set(self, holder: str, objective: str, value: int) -> None:
        """Set a score (value must already be a Java int). Creates the objective as ``dummy``
        if it does not exist, so test harnesses can seed scores before ``#load`` runs."""
        if not self.exists(objective):
            self.add_objective(objective)
        hid = self.holder_id(holder)
        oid = self.objective_ids[objective]
        self.values[hid, oid] = value
        self.present[hid, oid] = 1
        self.tracked.add(holder)  # getOrCreatePlayerInfo
        self.kept[hid] = 0

    def reset(self, holder: str, objective: str | None = None) -> None:
        """Unset one score, or every score of the holder when ``objective`` is None."""
        hid = self.holder_ids.get(holder)
        if hid is None:
            return
        if objective is None:
            self.present[hid, :] = 0
            self.locked[hid, :] = 1
        elif objective in self.objective_ids:
            oid = self.objective_ids[objective]
            self.present[hid, oid] = 0
            self.locked[hid, oid] = 1
        # resetAllPlayerScores drops the holder; resetSinglePlayerScore once it has no score left
        if objective is None or not self.present[hid].any():
            self.tracked.remove(holder)
            self.kept[hid] = 0

    def enable(self, holder: str, objective: str) -> bool:
        """``scoreboard players enable`` for one holder: get-or-create the score (0) and unlock
        it; True when it was locked (the command counts those and fails when there are none)."""
        if self.get(holder, objective) is None:
            self.set(holder, objective, 0)
        cell = self.holder_ids[holder], self.objective_ids[objective]
        was_locked = bool(self.locked[cell])
        self.locked[cell] = 0
        return was_locked

    def is_unlocked(self, holder: str, objective: str) -> bool:
        """True when the score exists and is unlocked: what ``trigger`` needs."""
        if self.get(holder, objective) is None:
            return False
        return not self.locked[self.holder_ids[holder], self.objective_ids[objective]]

    def lock(self, holder: str, objective: str) -> None:
        self.locked[self.holder_ids[holder], self.objective_ids[objective]] = 1

    def tracked_holders(self) -> list[str]:
        """What ``*`` names (Scoreboard.getTrackedPlayers): the holders of the game's score map in
        its hash order (:mod:`emulator.world.hash_order`), those whose scores went with a removed
        objective included.

        Python code changes scores through :meth:`set`/:meth:`reset`, which replay the map exactly.
        The VM writes ``present`` and ``kept`` directly, so the map is first brought up to date:
        holders the VM emptied leave it, holders it gave a first score (or whose only scores went
        with an objective it removed) join it in interning order (in the game, in the order of their
        first score; the two differ only for holders that collide in the table and were created
        between two uses of ``*``)."""
        n = len(self.holders)
        rows = self.present[:n].any(axis=1)
        for name in self.tracked.keys():
            h = self.holder_ids[name]
            if not rows[h] and not self.kept[h]:
                self.tracked.remove(name)
        for h in np.flatnonzero(rows | (self.kept[:n] != 0)):
            self.tracked.add(self.holders[h])
        self.kept[:n][rows] = 0
        return self.tracked.keys()

    def scores(self) -> dict[str, dict[str, int]]:
        """``{objective: {holder: value}}`` for every set score of every existing objective."""
        out: dict[str, dict[str, int]] = {}
        n = len(self.holders)
        for oid, name in enumerate(self.objectives):
            if not self.alive[oid]:
                continue
            rows = np.flatnonzero(self.present[:n, oid])
            out[name] = {self.holders[h]: int(self.values[h, oid]) for h in rows}
        return out


class ScoreReader:
    """``Scoreboard.block`` of fixed holders and objectives, their ids found once: calling it reads
    the block as it is now (int64 [holder, objective], 0 where unset) with a few array takes."""

    def __init__(self, board: Scoreboard, holders: list[str], objectives: list[str]) -> None:
        self.board, self.holders, self.objectives = board, holders, objectives
        self._values = None  # the scoreboard's values array the flat indices were made for

    def _index(self) -> bool:
        """Find the ids and flat indices again (the arrays grew, or a name was unknown): False while
        a holder or objective is unknown."""
        board = self.board
        hids = [board.holder_ids.get(h) for h in self.holders]
        oids = [board.objective_ids.get(o) for o in self.objectives]
        if None in hids or None in oids:
            return False
        self.oids = np.array(oids, dtype=np.int64)
        self.flat = (np.array(hids, dtype=np.int64)[:, None] * board.values.shape[1] + self.oids).ravel()
        self.shape = (len(hids), len(oids))
        self._values = board.values
        return True

    def __call__(self) -> np.ndarray:
        board = self.board
        if board.values is not self._values and not self._index():
            return board.block(self.holders, self.objectives)
        flat, shape = self.flat, self.shape
        known = board.present.ravel().take(flat).reshape(shape) & board.alive.take(self.oids)
        return board.values.ravel().take(flat).reshape(shape) * known.astype(np.int64)


def _grow(capacity: int, needed: int) -> int:
    while capacity < needed:
        capacity *= 2
    return capacity


# ---------------------------------------------------------------------- schedule queue
@dataclass(frozen=True, slots=True)
class ScheduledEntry:
    due: int  # gametime at which it runs
    seq: int  # insertion order (TimerQueue's sequentialId)
    function: str  # function or tag id, without '#'
    is_tag: bool

    @property
    def name(self) -> str:
        """The game's event name: the id, with '#' for a tag."""
        return ("#" if self.is_tag else "") + self.function


class ScheduleQueue:
    """The game's TimerQueue: events keyed by (name, due time), run by due time then insertion.

    Semantics (TimerQueue / ScheduleCommand, 1.21): ``replace`` removes every pending event of
    that name first; ``append`` keeps them, but an event with the same name *and* the same due
    time is not added twice.
    """

    def __init__(self) -> None:
        self._heap: list[tuple[int, int, ScheduledEntry]] = []
        self._live: dict[tuple[str, int], ScheduledEntry] = {}
        self._seq = itertools.count(1)

    def schedule(self, function_id: str, is_tag: bool, ticks: int, mode: str, gametime: int) -> int:
        """Schedule ``function_id`` ``ticks`` (>= 1) after ``gametime``; returns the due time.

        ``mode`` is ``"replace"`` or ``"append"``. (The command's own checks, such as ``0t``
        being rejected, are :func:`emulator.commands.server.schedule`'s.)
        """
        due = gametime + ticks
        name = ("#" if is_tag else "") + function_id
        if mode == "replace":
            self.clear(function_id, is_tag)
        if (name, due) not in self._live:
            entry = ScheduledEntry(due, next(self._seq), function_id, is_tag)
            self._live[(name, due)] = entry
            heapq.heappush(self._heap, (due, entry.seq, entry))
        return due

    def clear(self, function_id: str, is_tag: bool) -> int:
        """``schedule clear``: remove every pending event of that name; returns how many."""
        name = ("#" if is_tag else "") + function_id
        keys = [k for k in self._live if k[0] == name]
        for k in keys:
            del self._live[k]
        return len(keys)

    def pop_due(self, gametime: int) -> ScheduledEntry | None:
        """The next event due at or before ``gametime`` (removed from the queue), else None.

        Pop one at a time: an event run now may schedule or clear others.
        """
        while self._heap and self._heap[0][0] <= gametime:
            _, _, entry = heapq.heappop(self._heap)
            if self._live.get((entry.name, entry.due)) is entry:
                del self._live[(entry.name, entry.due)]
                return entry
        return None

    def next_due(self) -> int | None:
        """The due time of the next pending event, None when none is pending."""
        while self._heap and self._live.get((self._heap[0][2].name, self._heap[0][0])) is not self._heap[0][2]:
            heapq.heappop(self._heap)  # cleared or replaced: never runs
        return self._heap[0][0] if self._heap else None

    def pending(self) -> list[ScheduledEntry]:
        """Pending events in run order."""
        return sorted(self._live.values(), key=lambda e: (e.due, e.seq))


# ---------------------------------------------------------------------- gamerules
# Canonical key -> default, every rule of 1.20-1.21.10 (GameRules.register) and the 1.21.11+ rules
# whose meaning is new (the movement checks and raids turned from "disable" to "enabled", the fire's
# spread radius); aliases map the other 1.21.11+ snake_case names to the rule they renamed.
_TRUE_BY_DEFAULT = """
    doFireTick mobGriefing doMobSpawning doMobLoot projectilesCanBreakBlocks doTileDrops doEntityDrops
    commandBlockOutput naturalRegeneration doDaylightCycle logAdminCommands showDeathMessages sendCommandFeedback
    spectatorsGenerateChunks doWeatherCycle announceAdvancements doInsomnia drowningDamage fallDamage fireDamage
    freezeDamage doPatrolSpawning doTraderSpawning doWardenSpawning forgiveDeadPlayers blockExplosionDropDecay
    mobExplosionDropDecay waterSourceConversion globalSoundEvents doVinesSpread enderPearlsVanishOnDeath locatorBar
    tntExplodes allowEnteringNetherUsingPortals commandBlocksEnabled pvp spawnMonsters spawnerBlocksEnabled
    player_movement_check elytra_movement_check raids
""".split()
_FALSE_BY_DEFAULT = """
    keepInventory reducedDebugInfo disablePlayerMovementCheck disableElytraMovementCheck doLimitedCrafting
    disableRaids doImmediateRespawn universalAnger tntExplosionDropDecay lavaSourceConversion
    allowFireTicksAwayFromPlayer
""".split()
GAMERULE_DEFAULTS: dict[str, str] = {
    **dict.fromkeys(_TRUE_BY_DEFAULT, "true"), **dict.fromkeys(_FALSE_BY_DEFAULT, "false"),
    "randomTickSpeed": "3",
    "spawnRadius": "10",
    "maxEntityCramming": "24",
    "maxCommandChainLength": "65536",
    "maxCommandForkCount": "65536",
    "commandModificationBlockLimit": "32768",
    "playersNetherPortalDefaultDelay": "80",
    "playersNetherPortalCreativeDelay": "0",
    "playersSleepingPercentage": "100",
    "snowAccumulationHeight": "1",
    "minecartMaxSpeed": "8",
    "spawnChunkRadius": "2",
    "functionCommandPermissionLevel": "2",
    "fire_spread_radius_around_player": "128",
}
GAMERULE_ALIASES: dict[str, str] = dict(line.split() for line in """
max_command_sequence_length maxCommandChainLength
max_command_forks maxCommandForkCount
max_block_modifications commandModificationBlockLimit
send_command_feedback sendCommandFeedback
command_block_output commandBlockOutput
advance_time doDaylightCycle
advance_weather doWeatherCycle
random_tick_speed randomTickSpeed
keep_inventory keepInventory
show_death_messages showDeathMessages
immediate_respawn doImmediateRespawn
block_drops doTileDrops
mob_drops doMobLoot
allow_entering_nether_using_portals allowEnteringNetherUsingPortals
block_explosion_drop_decay blockExplosionDropDecay
command_blocks_work commandBlocksEnabled
drowning_damage drowningDamage
ender_pearls_vanish_on_death enderPearlsVanishOnDeath
entity_drops doEntityDrops
fall_damage fallDamage
fire_damage fireDamage
forgive_dead_players forgiveDeadPlayers
freeze_damage freezeDamage
global_sound_events globalSoundEvents
lava_source_conversion lavaSourceConversion
limited_crafting doLimitedCrafting
locator_bar locatorBar
log_admin_commands logAdminCommands
max_entity_cramming maxEntityCramming
max_minecart_speed minecartMaxSpeed
max_snow_accumulation_height snowAccumulationHeight
mob_explosion_drop_decay mobExplosionDropDecay
mob_griefing mobGriefing
natural_health_regeneration naturalRegeneration
players_nether_portal_creative_delay playersNetherPortalCreativeDelay
players_nether_portal_default_delay playersNetherPortalDefaultDelay
players_sleeping_percentage playersSleepingPercentage
projectiles_can_break_blocks projectilesCanBreakBlocks
reduced_debug_info reducedDebugInfo
respawn_radius spawnRadius
show_advancement_messages announceAdvancements
spawn_mobs doMobSpawning
spawn_monsters spawnMonsters
spawn_patrols doPatrolSpawning
spawn_phantoms doInsomnia
spawn_wandering_traders doTraderSpawning
spawn_wardens doWardenSpawning
spawner_blocks_work spawnerBlocksEnabled
spectators_generate_chunks spectatorsGenerateChunks
spread_vines doVinesSpread
tnt_explodes tntExplodes
tnt_explosion_drop_decay tntExplosionDropDecay
universal_anger universalAnger
water_source_conversion waterSourceConversion
""".strip().splitlines())


class Gamerules:
    """Gamerule values as strings, looked up under either spelling (``minecraft:`` prefix ok)."""

    def __init__(self) -> None:
        self.values: dict[str, str] = dict(GAMERULE_DEFAULTS)
        self._ints: dict[str, int] = {}  # get_int's answers, until a rule is set
        self._read_often()

    def _read_often(self) -> None:
        """The rules every root or tick reads, kept as plain attributes (read each time through
        :meth:`get_int`, they cost about a tenth of a one-command tick)."""
        self.max_command_chain_length = self.get_int("maxCommandChainLength")
        self.max_command_fork_count = self.get_int("maxCommandForkCount")
        self.daylight_cycle = self.values["doDaylightCycle"] == "true"
        self.weather_cycle = self.values["doWeatherCycle"] == "true"

    @staticmethod
    def canonical(name: str) -> str:
        name = name.removeprefix("minecraft:")
        return GAMERULE_ALIASES.get(name, name)

    def get(self, name: str) -> str | None:
        found = self.values.get(name)  # the canonical spelling (the emulator's own reads, every tick)
        return found if found is not None else self.values.get(self.canonical(name))

    def set(self, name: str, value: str) -> None:
        self.values[self.canonical(name)] = value
        self._ints.clear()
        self._read_often()

    def get_int(self, name: str) -> int:
        found = self._ints.get(name)
        if found is None:
            found = self._ints[name] = int(self.values[self.canonical(name)])
        return found


# ---------------------------------------------------------------------- the world
class WeakKeys(weakref.WeakKeyDictionary):
    """A WeakKeyDictionary whose truth test skips ``__len__`` (a Python method subtracting the keys
    being removed): the tick's steps ask each tick whether theirs is empty. True while only keys
    being removed are left, which those steps then find gone."""

    def __bool__(self) -> bool:
        return bool(self.data)


class WeakMembers(weakref.WeakSet):
    """A WeakSet whose truth test skips ``__len__`` (see :class:`WeakKeys`)."""

    def __bool__(self) -> bool:
        return bool(self.data)


@dataclass
class WorldState:
    """Everything a run mutates. ``tick`` counts server ticks run so far (the first tick is 0
    while it runs); ``gametime`` is the world's game time (advanced once per tick, before the
    scheduled functions of that tick run)."""

    scoreboard: Scoreboard = field(default_factory=Scoreboard)
    schedule: ScheduleQueue = field(default_factory=ScheduleQueue)
    gamerules: Gamerules = field(default_factory=Gamerules)
    gametime: int = 0
    daytime: int = 0  # the overworld's day time (time set/add; advances with doDaylightCycle); from 26.1 the overworld clock's ticks
    tick: int = 0
    log: list[LogEntry] = field(default_factory=list)
    diagnostics: list[RuntimeDiagnostic] = field(default_factory=list)
    overflows: list[Overflow] = field(default_factory=list)
    storage: StorageData = field(default_factory=StorageData)  # storage id -> nbt.Compound
    # the world's entities (creation order, UUIDs, seeded RNG) and blocks: see emulator.commands.entities
    entities: EntityStore = field(default_factory=EntityStore)
    blocks: BlockMap = field(default_factory=BlockMap)  # the overworld's; blocks_in(dimension) for any level's
    other_levels_blocks: dict = field(default_factory=dict)  # dimension id -> BlockMap
    block_ticks: BlockTicks = field(default_factory=BlockTicks)  # blocks' scheduled ticks (a button springing back)
    selector_cache: dict = field(default_factory=dict)  # id(ast.Selector) -> (node, SelectorQuery)
    random_sequences: RandomSequences = field(default_factory=RandomSequences)  # world seed 0
    bossbars: BossBars = field(default_factory=BossBars)
    advancement_progress: Progress = field(default_factory=Progress)  # each player's criteria
    using_items: dict = field(default_factory=dict)  # player -> the item it is using (emulator.world.player_actions)
    item_cooldowns: dict = field(default_factory=dict)  # player -> cooldown group -> its end tick (item_cooldowns)
    # what the game keeps on its entities without saving it, held weakly (a removed entity drops out)
    open_menus: weakref.WeakKeyDictionary = field(default_factory=WeakKeys)  # player -> (level, pos) (block_use)
    cameras: weakref.WeakKeyDictionary = field(default_factory=WeakKeys)  # player -> (camera, where it snapped) (spectating)
    trading: weakref.WeakKeyDictionary = field(default_factory=WeakKeys)  # merchant -> its trading player (mob_use)
    hurt_timers: weakref.WeakKeyDictionary = field(default_factory=WeakKeys)  # entity -> [invulnerableTime, lastHurt] (living)
    forced_chunks: dict = field(default_factory=dict)  # dimension -> the chunks (x, z) forceload marked
    cloud_victims: weakref.WeakKeyDictionary = field(default_factory=WeakKeys)  # area effect cloud -> {entity: until}
    swung: weakref.WeakKeyDictionary = field(default_factory=WeakKeys)  # player -> game time of its last swing (living)
    last_hurt_by: weakref.WeakKeyDictionary = field(default_factory=WeakKeys)  # entity -> (attacker, game time) (combat)
    last_attacker: weakref.WeakKeyDictionary = field(default_factory=WeakKeys)  # entity -> (living attacker, game time) (combat)
    combat_trackers: weakref.WeakKeyDictionary = field(default_factory=WeakKeys)  # living entity -> its CombatTracker (combat)
    dead_players: weakref.WeakSet = field(default_factory=WeakMembers)  # players that died, until they respawn (combat)
    crafting: dict = field(default_factory=dict)  # (level, pos) -> crafting ticks left of a crafter that crafted (crafters)
    brewing: dict = field(default_factory=dict)  # (level, pos) -> (block entity, the item it brews): not saved (brewing)
    falling: list = field(default_factory=list)  # players whose physics the server ticks (world.falling)
    protected: weakref.WeakKeyDictionary = field(default_factory=WeakKeys)  # player -> ticks it takes no damage (spawn_protection)
    moves: weakref.WeakKeyDictionary = field(default_factory=WeakKeys)  # player -> (from, to): its move this tick (falling)
    movers: tuple = (-1, None, [])  # (entity changes then, the store's list, the entities world.motion moves)
    hanging: tuple = (-1, None, [])  # (entity changes then, the store's list, the hanging entities: hanging_checks)
    hanging_counts: weakref.WeakKeyDictionary = field(default_factory=WeakKeys)  # entity -> checkInterval (hanging_checks)
    not_moving: weakref.WeakSet = field(default_factory=WeakMembers)  # their moves met what is not modelled (motion)
    ticks_lived: weakref.WeakKeyDictionary = field(default_factory=WeakKeys)  # entity -> Entity.tickCount (motion)
    flying: list = field(default_factory=list)  # projectiles made in flight, checked at the next tick (world.projectiles)
    command_runner: object = None  # runs a command block's text: (text, Context) -> successes (set by the runtime)
    teams: Teams = field(default_factory=Teams)  # the scoreboard's teams (emulator.world.teams)
    functions_named: object = None  # (name, is_tag) -> the ast.Function each names, in order (set by the runtime)
    pending_rewards: list = field(default_factory=list)  # (reward function, player) earned, to run next (take_rewards)
    random: random.Random = field(default_factory=lambda: random.Random(0))  # the level's random (predicates)
    version: tuple[int, int, int] = WORLD_RELEASE  # the game release the packs run as (LoadedPacks.version)
    resources: Resources = field(default_factory=Resources)  # loot, predicates, tags, advancements
    pack_repository: PackRepository = field(default_factory=PackRepository)  # the packs available and selected
    clocks: object = None  # 26.1+: the world clocks (emulator.world.clocks.WorldClocks)
    biomes: BiomeCells = field(default_factory=BiomeCells)  # the cells fillbiome set, per level (biomes)
    # False in the test server's world (GameTestServer: WorldOptions without generated structures);
    # None where the world's structures are not known (the emulator generates no terrain)
    structures_generated: bool | None = None
    weather: Weather = field(default_factory=Weather)  # the overworld's level data (emulator.world.weather)
    stopwatches: dict = field(default_factory=dict)  # id -> its start on the emulator's clock (emulator.world.stopwatches)
    level_settings: LevelSettings = field(default_factory=LevelSettings)  # spawn, border, difficulty (level_settings)
    # the day time Level.updateSkyBrightness last read (as the overworld starts and each tick, before
    # the time advances): Level.skyDarken is worked out from it when a light level is read
    sky_time: int = 0
    # the test whose commands run now (a PackTest helper: fail(message), succeed()), None outside a test:
    # what PackTest's commands run by a function reach (emulator.commands.packtest)
    test_helper: object = None
    _sky: tuple = field(default=(0, 0), repr=False, compare=False)  # (sky_time, its skyDarken)

    @property
    def sky_darken(self) -> int:
        """Level.skyDarken (:func:`emulator.world.light.sky_darken` of ``sky_time``)."""
        if self._sky[0] != self.sky_time:
            self._sky = (self.sky_time, light.sky_darken(self.sky_time))
        return self._sky[1]

    @sky_darken.setter
    def sky_darken(self, value: int) -> None:
        """Set as it is until the sky is next updated (tests darken the sky at will)."""
        self._sky = (self.sky_time, value)

    def __post_init__(self) -> None:
        self.entities.bind_scoreboard(self.scoreboard)
        self.entities.clock = lambda: self.tick
        self.entities.team_of = self.teams.team_of
        self.entities.join_team = self._join_team
        self.teams.on_change = self._team_changed
        self.blocks.version_of = self._release
        self.blocks.furnace_input_set = self._furnace_input_set

    def _join_team(self, holder: str, team: str) -> None:
        """A mob loaded with ``Team``: it joins that team when there is one (else the game logs a warning)."""
        if team in self.teams.teams:
            self.teams.join(self.teams.teams[team], [holder])

    def _team_changed(self, holder: str, team: str | None) -> None:
        """A score holder joined or left a team: so did the entities it names."""
        for entity in self.entities.entities:
            if entity.score_holder == holder:
                entity.team = team

    def _release(self) -> tuple:
        return self.version

    def _furnace_input_set(self, block_id: str, nbt, before, after, version) -> None:
        furnaces.input_set(self.resources, block_id, nbt, before, after, version)

    def discard(self, entity) -> None:
        """An entity removed for good (killed or discarded): out of the store, and, unless a player,
        its scores and its team with it (ServerLevel.EntityCallbacks.onDestroyed ->
        Scoreboard.entityRemoved: resetAllPlayerScores, removePlayerFromTeam)."""
        self.entities.kill(entity)
        if not entity.is_player:
            self.scoreboard.reset(entity.score_holder)
            self.teams.leave([entity.score_holder])

    def blocks_in(self, dimension: str) -> BlockMap:
        """The blocks of level ``dimension`` (each level has its own)."""
        if dimension == "minecraft:overworld":
            return self.blocks
        blocks = self.other_levels_blocks.get(dimension)
        if blocks is None:
            blocks = self.other_levels_blocks[dimension] = BlockMap(self._release)
            blocks.furnace_input_set = self._furnace_input_set
        return blocks

    def all_blocks(self) -> list[BlockMap]:
        """Every level's blocks, the overworld's first."""
        return [self.blocks, *self.other_levels_blocks.values()]

    def level(self, dimension: str) -> "LevelView":
        """The world as seen from level ``dimension`` (what the game's ServerLevel gives a block's
        code): its blocks and its block ticks; everything else is the world's."""
        return self if dimension == "minecraft:overworld" else LevelView(self, dimension)


    def emit(self, kind: str, text: str, loc: Loc | None = None, receivers: tuple[str, ...] = ()) -> None:
        self.log.append(LogEntry(self.tick, kind, text, loc, receivers))

    def broadcast(self, kind: str, text: str, loc: Loc | None = None) -> None:
        """A message every player online receives (PlayerList.broadcastSystemMessage / broadcastChatMessage)."""
        self.emit(kind, text, loc, tuple(p.uuid_string for p in self.entities.players()))

    def unmodelled_once(self, what: str, reason) -> None:
        """A world step met what is not modelled (``reason``, an Unmodelled): one warning per
        message, ``what: <the reason>``, for the whole run."""
        message = f"{what}: {reason.message.removeprefix('not modelled: ')}"
        if not any(d.message == message for d in self.diagnostics):
            self.error(message, severity="warning", unmodelled=True)

    def error(self, message: str, frames: tuple[Frame, ...] = (), severity: str = "error",
              unmodelled: bool = False) -> None:
        self.diagnostics.append(RuntimeDiagnostic(self.tick, message, frames, severity, unmodelled))


class LevelView:
    """:meth:`WorldState.level` for a level other than the overworld: ``blocks`` and ``block_ticks``
    are that level's, every other attribute is the world's."""

    def __init__(self, state: WorldState, dimension: str) -> None:
        self._state, self.dimension = state, dimension
        self.blocks = state.blocks_in(dimension)
        self.block_ticks = state.block_ticks.in_level(dimension)

    def __getattr__(self, name: str):
        return getattr(self._state, name)
