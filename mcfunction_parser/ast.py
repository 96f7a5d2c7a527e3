"""The typed AST of mcfunction commands.

Every node is a frozen, slotted dataclass (run released: immutable by convention, see
:mod:`.frozen_init`) carrying ``loc`` (file, line, column of its first
character). A command is identified by its class; commands the emulator only needs to count, log or
run host-side (``tellraw``, ``particle``, ``setblock`` ...) are ``GenericCommand`` with their text.

Conventions
- Resource locations are normalised strings with a namespace (``minecraft:tick``); a tag reference
  keeps the flag separately (``is_tag=True``) rather than a leading ``#``.
- Optional arguments absent in the source are ``None``.
- SNBT values use the types of :mod:`mcfunction_parser.nbt`.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Union

from .diagnostics import Loc
from .nbt import Compound

# ----------------------------------------------------------------------------- values


@dataclass(frozen=True, slots=True)
class IntRange:
    """``1..5``, ``..0``, ``3``: inclusive bounds, None for an open end."""

    lo: int | None
    hi: int | None

    def contains(self, value: int) -> bool:
        return (self.lo is None or value >= self.lo) and (self.hi is None or value <= self.hi)


@dataclass(frozen=True, slots=True)
class FloatRange:
    lo: float | None
    hi: float | None

    def contains(self, value: float) -> bool:
        return (self.lo is None or value >= self.lo) and (self.hi is None or value <= self.hi)


@dataclass(frozen=True, slots=True)
class Coord:
    """One coordinate: ``kind`` is ``"abs"``, ``"rel"`` (``~``) or ``"local"`` (``^``).

    ``is_int`` records an integer literal written without a decimal point; for block positions
    and for absolute x/z of entity positions the game treats those differently (centres x/z: +0.5).
    """

    kind: str
    value: float
    is_int: bool = False


@dataclass(frozen=True, slots=True)
class Vec3:
    """A position argument; all three coordinates are local or none is."""

    x: Coord
    y: Coord
    z: Coord
    loc: Loc

    @property
    def is_local(self) -> bool:
        return self.x.kind == "local"


@dataclass(frozen=True, slots=True)
class Vec2:
    """A rotation (yaw, pitch) or a column position (x, z); coordinates are ``abs`` or ``rel``."""

    x: Coord
    y: Coord
    loc: Loc


@dataclass(frozen=True, slots=True)
class SelectorArg:
    """One ``key=value`` inside ``@e[...]``.

    Value types by key: ``type``/``tag``/``name``/``team``/``gamemode``/``predicate``: str
    (``type`` and ``predicate`` normalised resource locations; a ``type`` entity-type tag keeps its
    ``#``); ``limit``: int; ``sort``: str; ``x y z dx dy dz``: float; ``distance``,
    ``x_rotation``, ``y_rotation``: FloatRange; ``level``: IntRange; ``scores``:
    tuple[tuple[str, IntRange], ...]; ``nbt``: Compound; ``advancements``: str (raw text).
    """

    key: str
    value: Any
    negated: bool
    loc: Loc


@dataclass(frozen=True, slots=True)
class Selector:
    """``@s @e @a @p @r @n`` with arguments."""

    variable: str  # "s", "e", "a", "p", "r", "n"
    args: tuple[SelectorArg, ...]
    loc: Loc

    def get(self, key: str) -> list[SelectorArg]:
        return [a for a in self.args if a.key == key]


@dataclass(frozen=True, slots=True)
class NameTarget:
    """A player name, fake-player name (``#x``, ``$y``) or UUID used where a target is expected."""

    name: str
    loc: Loc
    is_uuid: bool = False


@dataclass(frozen=True, slots=True)
class Wildcard:
    """``*`` as a score holder: every holder with a score in the objective."""

    loc: Loc


Target = Union[Selector, NameTarget]
ScoreHolder = Union[Selector, NameTarget, Wildcard]


# NBT paths: a root compound filter `{a:1}`, then keys, indexes and filters.
@dataclass(frozen=True, slots=True)
class PathKey:
    name: str


@dataclass(frozen=True, slots=True)
class PathIndex:
    index: int


@dataclass(frozen=True, slots=True)
class PathAll:
    """``[]``: every element of a list."""


@dataclass(frozen=True, slots=True)
class PathMatch:
    """``[{...}]``: every list element that matches the compound."""

    pattern: Compound


@dataclass(frozen=True, slots=True)
class PathFilter:
    """``{...}`` after a key (``a{b:1}``) or as the root: the current compound must match."""

    pattern: Compound


PathNode = Union[PathKey, PathIndex, PathAll, PathMatch, PathFilter]


@dataclass(frozen=True, slots=True)
class NbtPath:
    nodes: tuple[PathNode, ...]
    text: str
    loc: Loc


@dataclass(frozen=True, slots=True)
class EntityData:
    target: Target
    loc: Loc


@dataclass(frozen=True, slots=True)
class StorageData:
    id: str
    loc: Loc


@dataclass(frozen=True, slots=True)
class BlockData:
    pos: Vec3
    loc: Loc


DataTarget = Union[EntityData, StorageData, BlockData]


# ----------------------------------------------------------------------------- commands


@dataclass(frozen=True, slots=True)
class Command:
    loc: Loc


@dataclass(frozen=True, slots=True)
class GenericCommand(Command):
    """A command the AST keeps as text: ``name`` is its first word, ``text`` the whole command."""

    name: str
    text: str


@dataclass(frozen=True, slots=True)
class UnreadCommand(Command):
    """A line of a release newer than every command tree dpemu has that its readers refuse: kept,
    so the function loads as it may in that release, with ``reason`` (why it was not read); running
    it is not modelled."""

    name: str
    text: str
    reason: str


@dataclass(frozen=True, slots=True)
class MacroLine(Command):
    """A ``$`` line; ``template`` is the text after ``$`` with ``$(key)`` placeholders intact."""

    template: str
    keys: tuple[str, ...]


# scoreboard objectives ...
@dataclass(frozen=True, slots=True)
class ObjectivesAdd(Command):
    objective: str
    criterion: str
    display_name: str | None  # JSON text, as written


@dataclass(frozen=True, slots=True)
class ObjectivesRemove(Command):
    objective: str


@dataclass(frozen=True, slots=True)
class ObjectivesModify(Command):
    objective: str
    field: str  # "displayname", "rendertype", "displayautoupdate", "numberformat"
    value: str


@dataclass(frozen=True, slots=True)
class ObjectivesSetdisplay(Command):
    slot: str
    objective: str | None


@dataclass(frozen=True, slots=True)
class ObjectivesList(Command):
    pass


# scoreboard players ...
@dataclass(frozen=True, slots=True)
class ScoreSet(Command):
    """``scoreboard players set|add|remove``; ``action`` is ``"set"``, ``"add"`` or ``"remove"``."""

    action: str
    targets: ScoreHolder
    objective: str
    value: int


@dataclass(frozen=True, slots=True)
class ScoreReset(Command):
    targets: ScoreHolder
    objective: str | None


@dataclass(frozen=True, slots=True)
class ScoreGet(Command):
    target: ScoreHolder
    objective: str


@dataclass(frozen=True, slots=True)
class ScoreEnable(Command):
    targets: ScoreHolder
    objective: str


@dataclass(frozen=True, slots=True)
class ScoreOperation(Command):
    """``op`` is one of ``= += -= *= /= %= < > ><``."""

    targets: ScoreHolder
    objective: str
    op: str
    sources: ScoreHolder
    source_objective: str


@dataclass(frozen=True, slots=True)
class ScoreList(Command):
    target: ScoreHolder | None


@dataclass(frozen=True, slots=True)
class ScoreDisplay(Command):
    """``scoreboard players display name|numberformat ...``, kept as text after ``display``."""

    text: str


# execute ...
@dataclass(frozen=True, slots=True)
class Subcommand:
    loc: Loc


@dataclass(frozen=True, slots=True)
class ExAs(Subcommand):
    targets: Target


@dataclass(frozen=True, slots=True)
class ExAt(Subcommand):
    targets: Target


@dataclass(frozen=True, slots=True)
class ExPositioned(Subcommand):
    pos: Vec3


@dataclass(frozen=True, slots=True)
class ExPositionedAs(Subcommand):
    targets: Target


@dataclass(frozen=True, slots=True)
class ExPositionedOver(Subcommand):
    heightmap: str


@dataclass(frozen=True, slots=True)
class ExRotated(Subcommand):
    rot: Vec2


@dataclass(frozen=True, slots=True)
class ExRotatedAs(Subcommand):
    targets: Target


@dataclass(frozen=True, slots=True)
class ExFacing(Subcommand):
    pos: Vec3


@dataclass(frozen=True, slots=True)
class ExFacingEntity(Subcommand):
    targets: Target
    anchor: str  # "eyes" | "feet"


@dataclass(frozen=True, slots=True)
class ExAnchored(Subcommand):
    anchor: str


@dataclass(frozen=True, slots=True)
class ExAlign(Subcommand):
    axes: str  # any of "xyz", no repeats


@dataclass(frozen=True, slots=True)
class ExIn(Subcommand):
    dimension: str


@dataclass(frozen=True, slots=True)
class ExOn(Subcommand):
    relation: str  # attacker, controller, leasher, origin, owner, passengers, target, vehicle


@dataclass(frozen=True, slots=True)
class ExSummon(Subcommand):
    entity_type: str


@dataclass(frozen=True, slots=True)
class Condition(Subcommand):
    """Base of ``if``/``unless`` subcommands; ``negated`` is True for ``unless``."""

    negated: bool


@dataclass(frozen=True, slots=True)
class IfScore(Condition):
    """``if score T o OP S o2``; ``op`` is one of ``< <= = >= >``."""

    target: ScoreHolder
    objective: str
    op: str
    source: ScoreHolder
    source_objective: str


@dataclass(frozen=True, slots=True)
class IfScoreMatches(Condition):
    target: ScoreHolder
    objective: str
    range: IntRange


@dataclass(frozen=True, slots=True)
class IfEntity(Condition):
    targets: Target


@dataclass(frozen=True, slots=True)
class IfData(Condition):
    source: DataTarget
    path: NbtPath


@dataclass(frozen=True, slots=True)
class IfBlock(Condition):
    pos: Vec3
    block: str  # block predicate as written: id or #tag, optional [states] and {nbt}


@dataclass(frozen=True, slots=True)
class IfBlocks(Condition):
    start: Vec3
    end: Vec3
    destination: Vec3
    mode: str  # "all" | "masked"


@dataclass(frozen=True, slots=True)
class IfFunction(Condition):
    function: str
    is_tag: bool


@dataclass(frozen=True, slots=True)
class IfPredicate(Condition):
    predicate: str  # resource location, or inline JSON/SNBT text


@dataclass(frozen=True, slots=True)
class IfBiome(Condition):
    pos: Vec3
    biome: str


@dataclass(frozen=True, slots=True)
class IfLoaded(Condition):
    pos: Vec3


@dataclass(frozen=True, slots=True)
class IfDimension(Condition):
    dimension: str


@dataclass(frozen=True, slots=True)
class IfItems(Condition):
    """``if items entity|block SOURCE SLOTS PREDICATE``: ``source`` an :class:`ItemTarget`."""

    source: "ItemTarget"
    slots: "SlotArgument"
    predicate: "ItemPredicate"


@dataclass(frozen=True, slots=True)
class IfStopwatch(Condition):
    """``if stopwatch ID RANGE`` (1.21.11+): the stopwatch's elapsed seconds are in the range."""

    stopwatch: str
    range: FloatRange


@dataclass(frozen=True, slots=True)
class StoreScore(Subcommand):
    """``store result|success score``; ``kind`` is ``"result"`` or ``"success"``."""

    kind: str
    targets: ScoreHolder
    objective: str


@dataclass(frozen=True, slots=True)
class StoreData(Subcommand):
    """``store result|success entity|storage|block PATH TYPE SCALE``; type is byte/short/int/long/float/double."""

    kind: str
    target: DataTarget
    path: NbtPath
    type: str
    scale: float


@dataclass(frozen=True, slots=True)
class StoreBossbar(Subcommand):
    kind: str
    bossbar: str
    field: str  # "value" | "max"


@dataclass(frozen=True, slots=True)
class Execute(Command):
    subcommands: tuple[Subcommand, ...]
    run: Command | None  # None when the chain ends without ``run``


# functions
@dataclass(frozen=True, slots=True)
class FunctionCall(Command):
    """``function NAME [ARGS | with SOURCE [PATH]]``."""

    function: str
    is_tag: bool
    arguments: Compound | None = None
    with_source: DataTarget | None = None
    with_path: NbtPath | None = None


@dataclass(frozen=True, slots=True)
class Return(Command):
    """``return N`` (kind ``"value"``), ``return run CMD`` (``"run"``), ``return fail`` (``"fail"``)."""

    kind: str
    value: int | None = None
    command: Command | None = None


@dataclass(frozen=True, slots=True)
class Schedule(Command):
    function: str
    is_tag: bool
    ticks: int  # converted from t/s/d
    mode: str  # "replace" | "append"


@dataclass(frozen=True, slots=True)
class ScheduleClear(Command):
    function: str
    is_tag: bool


# data
@dataclass(frozen=True, slots=True)
class DataGet(Command):
    target: DataTarget
    path: NbtPath | None
    scale: float | None


@dataclass(frozen=True, slots=True)
class DataMerge(Command):
    target: DataTarget
    nbt: Compound


@dataclass(frozen=True, slots=True)
class SourceValue:
    value: Any  # an NBT value
    loc: Loc


@dataclass(frozen=True, slots=True)
class SourceFrom:
    source: DataTarget
    path: NbtPath | None
    loc: Loc


@dataclass(frozen=True, slots=True)
class SourceString:
    """``string SOURCE [PATH] [START] [END]``."""

    source: DataTarget
    path: NbtPath | None
    start: int | None
    end: int | None
    loc: Loc


DataSource = Union[SourceValue, SourceFrom, SourceString]


@dataclass(frozen=True, slots=True)
class DataModify(Command):
    """``mode`` is set, append, prepend, insert (with ``index``) or merge."""

    target: DataTarget
    path: NbtPath
    mode: str
    index: int | None
    source: DataSource


@dataclass(frozen=True, slots=True)
class DataRemove(Command):
    target: DataTarget
    path: NbtPath


# entities
@dataclass(frozen=True, slots=True)
class TagCommand(Command):
    """``tag TARGETS add|remove NAME`` or ``tag TARGETS list`` (``name`` None)."""

    targets: Target
    action: str
    name: str | None


@dataclass(frozen=True, slots=True)
class Summon(Command):
    entity_type: str
    pos: Vec3 | None
    nbt: Compound | None


@dataclass(frozen=True, slots=True)
class Kill(Command):
    targets: Target | None  # None: the executor


@dataclass(frozen=True, slots=True)
class Teleport(Command):
    """All ``tp``/``teleport`` forms.

    - ``tp DEST_ENTITY``: targets None, destination a Target.
    - ``tp POS``: targets None, destination a Vec3.
    - ``tp TARGETS DEST_ENTITY`` / ``tp TARGETS POS [ROT | facing POS | facing entity E [ANCHOR]]``.
    """

    targets: Target | None
    destination: Union[Vec3, Target]
    rotation: Vec2 | None = None
    facing: Vec3 | None = None
    facing_entity: Target | None = None
    facing_anchor: str | None = None


# server state
@dataclass(frozen=True, slots=True)
class Gamerule(Command):
    rule: str
    value: str | None  # None: query


@dataclass(frozen=True, slots=True)
class RandomCommand(Command):
    """``random value|roll RANGE [SEQUENCE]`` or ``random reset SEQUENCE|* [SEED [INCLUDE_WORLD INCLUDE_SEQ]]``."""

    action: str
    range: IntRange | None
    sequence: str | None
    seed: int | None = None
    include_world_seed: bool = True
    include_sequence_id: bool = True


@dataclass(frozen=True, slots=True)
class Time(Command):
    """``time add|set|query``; ``value`` in ticks for add/set (``day``, ``night`` ... converted)."""

    action: str
    value: int | None
    query: str | None  # "daytime" | "gametime" | "day"


@dataclass(frozen=True, slots=True)
class ClockCommand(Command):
    """``time`` on a world clock, from 26.1 (every form but ``time query gametime``, which is
    :class:`Time`). ``clock``: the clock's id (``time of <clock> ...``), None for the default clock
    of the executing dimension. ``action``: ``set``/``add`` (``value`` in ticks), ``marker``
    (``time set <time marker>``: ``value`` the marker's id), ``pause``, ``resume``, ``rate``
    (``value`` a float), ``query`` (``timeline``: None for ``query time``, else the timeline's id;
    ``repetition`` for ``... repetition``). Ids carry their namespace; ``clock_loc`` and
    ``timeline_loc`` are where they are written (the game looks both up when it loads the function)."""

    action: str
    clock: str | None = None
    value: Any = None
    timeline: str | None = None
    repetition: bool = False
    clock_loc: Loc | None = None
    timeline_loc: Loc | None = None


@dataclass(frozen=True, slots=True)
class Ride(Command):
    """``ride TARGET mount VEHICLE`` or ``ride TARGET dismount`` (1.19.4+)."""

    target: Target
    action: str  # "mount" | "dismount"
    vehicle: Target | None = None


@dataclass(frozen=True, slots=True)
class Bossbar(Command):
    """``bossbar add|remove|list|set|get``. ``field``: the property ``set``/``get`` name (name,
    color, style, value, max, visible, players); ``text``: the name component as written (add,
    set name) or the color/style word; ``number``: set value|max; ``flag``: set visible;
    ``targets``: set players TARGETS (None: nobody)."""

    action: str
    id: str | None
    field: str | None = None
    text: str | None = None
    number: int | None = None
    flag: bool | None = None
    targets: Target | None = None


@dataclass(frozen=True, slots=True)
class Trigger(Command):
    objective: str
    action: str | None  # None (increment by 1), "add", "set"
    value: int | None


@dataclass(frozen=True, slots=True)
class Say(Command):
    message: str


@dataclass(frozen=True, slots=True)
class Tellraw(Command):
    targets: Target
    text: str  # JSON/SNBT text component, as written


# ----------------------------------------------------------------------------- files and packs


@dataclass(frozen=True, slots=True)
class Function:
    """One .mcfunction file: ``id`` is ``ns:path``; ``commands`` in order; ``is_macro`` if any ``$`` line."""

    id: str
    path: str
    commands: tuple[Command, ...]
    lines: int
    is_macro: bool = False
    pack: str = ""


@dataclass(slots=True)
class TagEntry:
    id: str
    is_tag: bool
    required: bool
    loc: Loc


@dataclass(slots=True)
class FunctionTag:
    """A function tag after merging every pack's file (``replace`` honoured); entries in order."""

    id: str
    entries: list[TagEntry] = field(default_factory=list)


# ----------------------------------------------------------------------------- items


@dataclass(frozen=True, slots=True)
class ItemArgument:
    """An item to create (ItemArgument): ``id[component=value,!component]`` from 1.20.5, ``id{tag}``
    before. ``components`` are (namespaced component id, SNBT value) in the order written;
    ``removed`` the ``!component`` ids; ``tag`` the older NBT form (None when absent)."""

    loc: Loc
    id: str
    components: tuple[tuple[str, Any], ...] = ()
    removed: tuple[str, ...] = ()
    tag: Compound | None = None


@dataclass(frozen=True, slots=True)
class ComponentTest:
    """One test inside an item predicate's brackets: ``component`` (exists), ``component=value``
    (the component equals the value), ``predicate~value`` (a sub-predicate); ``count`` with either
    takes an int or ``{min, max}``;
    ``negated`` for a leading ``!``."""

    name: str
    kind: str  # "exists", "=", "~"
    value: Any = None
    negated: bool = False


@dataclass(frozen=True, slots=True)
class ItemPredicate:
    """ItemPredicateArgument: ``id``, ``#tag`` or ``*`` (``id`` None), then ``[...]`` tests (from
    1.20.5: a tuple of any-of groups, all of which must pass) or ``{nbt}`` (older: a partial match
    of the stack's ``tag``)."""

    loc: Loc
    id: str | None
    is_tag: bool = False
    tests: tuple[tuple[ComponentTest, ...], ...] = ()
    tag: Compound | None = None


@dataclass(frozen=True, slots=True)
class SlotArgument:
    """A slot name (SlotArgument / SlotsArgument) and the slot ids it names (several for a range
    such as ``container.*``)."""

    name: str
    ids: tuple[int, ...]


@dataclass(frozen=True, slots=True)
class ItemTarget:
    """Where items go or come from: ``entity TARGETS`` or ``block POS``."""

    kind: str  # "entity" or "block"
    target: Target | Vec3  # a selector/name for entities, a position for blocks


@dataclass(frozen=True, slots=True)
class ResourceOrInline:
    """ResourceOrIdArgument: a loot table / item modifier / predicate id, or (from 1.20.5) an
    inline definition written as SNBT; ``inline`` holds it converted to JSON values."""

    id: str | None
    inline: Any = None
    text: str = ""


@dataclass(frozen=True, slots=True)
class Give(Command):
    targets: Target
    item: ItemArgument
    count: int = 1


@dataclass(frozen=True, slots=True)
class Clear(Command):
    targets: Target | None = None  # None: the executor
    item: ItemPredicate | None = None
    max_count: int | None = None


@dataclass(frozen=True, slots=True)
class ItemReplace(Command):
    """``item replace TARGET SLOT with ITEM [COUNT]`` (``item`` set) or ``... from SOURCE SLOT
    [MODIFIER]`` (``source`` set)."""

    target: ItemTarget
    slot: SlotArgument
    item: ItemArgument | None = None
    count: int | None = None
    source: ItemTarget | None = None
    source_slot: SlotArgument | None = None
    modifier: ResourceOrInline | None = None


@dataclass(frozen=True, slots=True)
class ItemModify(Command):
    target: ItemTarget
    slot: SlotArgument
    modifier: ResourceOrInline


@dataclass(frozen=True, slots=True)
class Loot(Command):
    """``loot TARGET SOURCE``. ``action`` is give|insert|spawn|replace; ``destination`` the
    players (give), a position (insert, spawn) or an :class:`ItemTarget` (replace) with ``slot``
    and ``count``. ``source`` is fish|loot|kill|mine with ``table``, ``pos`` (fish, mine), ``tool``
    (an :class:`ItemArgument`, ``"mainhand"``/``"offhand"`` or None) and ``entity`` (kill)."""

    action: str
    destination: Target | Vec3 | ItemTarget
    source: str
    slot: SlotArgument | None = None
    count: int | None = None
    table: ResourceOrInline | None = None
    pos: Vec3 | None = None
    tool: ItemArgument | str | None = None
    entity: Target | None = None


from .frozen_init import speed_up_inits  # noqa: E402

speed_up_inits(globals())  # the same nodes, built faster (see frozen_init)
