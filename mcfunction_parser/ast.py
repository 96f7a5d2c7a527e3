"""The typed AST of mcfunction commands.

Every node is a frozen, slotted dataclass (declared with :func:`.frozen_init.node`; run released:
immutable by convention, see :mod:`.frozen_init`) carrying ``loc`` (file, line, column of its first
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
from .frozen_init import node
from .nbt import Compound

# ----------------------------------------------------------------------------- values


@node
class IntRange:
    """``1..5``, ``..0``, ``3``: inclusive bounds, None for an open end."""

    lo: int | None
    hi: int | None

    def contains(self, value: int) -> bool:
        return (self.lo is None or value >= self.lo) and (self.hi is None or value <= self.hi)


@node
class FloatRange:
    lo: float | None
    hi: float | None

    def contains(self, value: float) -> bool:
        return (self.lo is None or value >= self.lo) and (self.hi is None or value <= self.hi)


@node
class Coord:
    """One coordinate: ``kind`` is ``"abs"``, ``"rel"`` (``~``) or ``"local"`` (``^``).

    ``is_int`` records an integer literal written without a decimal point; for block positions
    and for absolute x/z of entity positions the game treats those differently (centres x/z: +0.5).
    """

    kind: str
    value: float
    is_int: bool = False


@node
class Vec3:
    """A position argument; all three coordinates are local or none is."""

    x: Coord
    y: Coord
    z: Coord
    loc: Loc

    @property
    def is_local(self) -> bool:
        return self.x.kind == "local"


@node
class Vec2:
    """A rotation (yaw, pitch) or a column position (x, z); coordinates are ``abs`` or ``rel``."""

    x: Coord
    y: Coord
    loc: Loc


@node
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


@node
class Selector:
    """``@s @e @a @p @r @n`` with arguments."""

    variable: str  # "s", "e", "a", "p", "r", "n"
    args: tuple[SelectorArg, ...]
    loc: Loc

    def get(self, key: str) -> list[SelectorArg]:
        return [a for a in self.args if a.key == key]


@node
class NameTarget:
    """A player name, fake-player name (``#x``, ``$y``) or UUID used where a target is expected."""

    name: str
    loc: Loc
    is_uuid: bool = False


@node
class Wildcard:
    """``*`` as a score holder: every holder with a score in the objective."""

    loc: Loc


Target = Union[Selector, NameTarget]
ScoreHolder = Union[Selector, NameTarget, Wildcard]


# NBT paths: a root compound filter `{a:1}`, then keys, indexes and filters.
@node
class PathKey:
    name: str


@node
class PathIndex:
    index: int


@node
class PathAll:
    """``[]``: every element of a list."""


@node
class PathMatch:
    """``[{...}]``: every list element that matches the compound."""

    pattern: Compound


@node
class PathFilter:
    """``{...}`` after a key (``a{b:1}``) or as the root: the current compound must match."""

    pattern: Compound


PathNode = Union[PathKey, PathIndex, PathAll, PathMatch, PathFilter]


@node
class NbtPath:
    nodes: tuple[PathNode, ...]
    text: str
    loc: Loc


@node
class EntityData:
    target: Target
    loc: Loc


@node
class StorageData:
    id: str
    loc: Loc


@node
class BlockData:
    pos: Vec3
    loc: Loc


DataTarget = Union[EntityData, StorageData, BlockData]


# ----------------------------------------------------------------------------- commands


@node
class Command:
    loc: Loc


@node
class GenericCommand(Command):
    """A command the AST keeps as text: ``name`` is its first word, ``text`` the whole command."""

    name: str
    text: str


@node
class UnreadCommand(Command):
    """A line of a release newer than every command tree dpemu has that its readers refuse: kept,
    so the function loads as it may in that release, with ``reason`` (why it was not read); running
    it is not modelled."""

    name: str
    text: str
    reason: str


@node
class MacroLine(Command):
    """A ``$`` line; ``template`` is the text after ``$`` with ``$(key)`` placeholders intact."""

    template: str
    keys: tuple[str, ...]


# scoreboard objectives ...
@node
class ObjectivesAdd(Command):
    objective: str
    criterion: str
    display_name: str | None  # JSON text, as written


@node
class ObjectivesRemove(Command):
    objective: str


@node
class ObjectivesModify(Command):
    objective: str
    field: str  # "displayname", "rendertype", "displayautoupdate", "numberformat"
    value: str


@node
class ObjectivesSetdisplay(Command):
    slot: str
    objective: str | None


@node
class ObjectivesList(Command):
    pass


# scoreboard players ...
@node
class ScoreSet(Command):
    """``scoreboard players set|add|remove``; ``action`` is ``"set"``, ``"add"`` or ``"remove"``."""

    action: str
    targets: ScoreHolder
    objective: str
    value: int


@node
class ScoreReset(Command):
    targets: ScoreHolder
    objective: str | None


@node
class ScoreGet(Command):
    target: ScoreHolder
    objective: str


@node
class ScoreEnable(Command):
    targets: ScoreHolder
    objective: str


@node
class ScoreOperation(Command):
    """``op`` is one of ``= += -= *= /= %= < > ><``."""

    targets: ScoreHolder
    objective: str
    op: str
    sources: ScoreHolder
    source_objective: str


@node
class ScoreList(Command):
    target: ScoreHolder | None


@node
class ScoreDisplay(Command):
    """``scoreboard players display name|numberformat ...``, kept as text after ``display``."""

    text: str


# execute ...
@node
class Subcommand:
    loc: Loc


@node
class ExAs(Subcommand):
    targets: Target


@node
class ExAt(Subcommand):
    targets: Target


@node
class ExPositioned(Subcommand):
    pos: Vec3


@node
class ExPositionedAs(Subcommand):
    targets: Target


@node
class ExPositionedOver(Subcommand):
    heightmap: str


@node
class ExRotated(Subcommand):
    rot: Vec2


@node
class ExRotatedAs(Subcommand):
    targets: Target


@node
class ExFacing(Subcommand):
    pos: Vec3


@node
class ExFacingEntity(Subcommand):
    targets: Target
    anchor: str  # "eyes" | "feet"


@node
class ExAnchored(Subcommand):
    anchor: str


@node
class ExAlign(Subcommand):
    axes: str  # any of "xyz", no repeats


@node
class ExIn(Subcommand):
    dimension: str


@node
class ExOn(Subcommand):
    relation: str  # attacker, controller, leasher, origin, owner, passengers, target, vehicle


@node
class ExSummon(Subcommand):
    entity_type: str


@node
class Condition(Subcommand):
    """Base of ``if``/``unless`` subcommands; ``negated`` is True for ``unless``."""

    negated: bool


@node
class IfScore(Condition):
    """``if score T o OP S o2``; ``op`` is one of ``< <= = >= >``."""

    target: ScoreHolder
    objective: str
    op: str
    source: ScoreHolder
    source_objective: str


@node
class IfScoreMatches(Condition):
    target: ScoreHolder
    objective: str
    range: IntRange


@node
class IfEntity(Condition):
    targets: Target


@node
class IfData(Condition):
    source: DataTarget
    path: NbtPath


@node
class IfBlock(Condition):
    pos: Vec3
    block: str  # block predicate as written: id or #tag, optional [states] and {nbt}


@node
class IfBlocks(Condition):
    start: Vec3
    end: Vec3
    destination: Vec3
    mode: str  # "all" | "masked"


@node
class IfFunction(Condition):
    function: str
    is_tag: bool


@node
class IfPredicate(Condition):
    predicate: str  # resource location, or inline JSON/SNBT text


@node
class IfBiome(Condition):
    pos: Vec3
    biome: str


@node
class IfLoaded(Condition):
    pos: Vec3


@node
class IfDimension(Condition):
    dimension: str


@node
class IfItems(Condition):
    """``if items entity|block SOURCE SLOTS PREDICATE``: ``source`` an :class:`ItemTarget`."""

    source: "ItemTarget"
    slots: "SlotArgument"
    predicate: "ItemPredicate"


@node
class IfStopwatch(Condition):
    """``if stopwatch ID RANGE`` (1.21.11+): the stopwatch's elapsed seconds are in the range."""

    stopwatch: str
    range: FloatRange


@node
class StoreScore(Subcommand):
    """``store result|success score``; ``kind`` is ``"result"`` or ``"success"``."""

    kind: str
    targets: ScoreHolder
    objective: str


@node
class StoreData(Subcommand):
    """``store result|success entity|storage|block PATH TYPE SCALE``; type is byte/short/int/long/float/double."""

    kind: str
    target: DataTarget
    path: NbtPath
    type: str
    scale: float


@node
class StoreBossbar(Subcommand):
    kind: str
    bossbar: str
    field: str  # "value" | "max"


@node
class Execute(Command):
    subcommands: tuple[Subcommand, ...]
    run: Command | None  # None when the chain ends without ``run``


# functions
@node
class FunctionCall(Command):
    """``function NAME [ARGS | with SOURCE [PATH]]``."""

    function: str
    is_tag: bool
    arguments: Compound | None = None
    with_source: DataTarget | None = None
    with_path: NbtPath | None = None


@node
class Return(Command):
    """``return N`` (kind ``"value"``), ``return run CMD`` (``"run"``), ``return fail`` (``"fail"``)."""

    kind: str
    value: int | None = None
    command: Command | None = None


@node
class Schedule(Command):
    function: str
    is_tag: bool
    ticks: int  # converted from t/s/d
    mode: str  # "replace" | "append"


@node
class ScheduleClear(Command):
    function: str
    is_tag: bool


# data
@node
class DataGet(Command):
    target: DataTarget
    path: NbtPath | None
    scale: float | None


@node
class DataMerge(Command):
    target: DataTarget
    nbt: Compound


@node
class SourceValue:
    value: Any  # an NBT value
    loc: Loc


@node
class SourceFrom:
    source: DataTarget
    path: NbtPath | None
    loc: Loc


@node
class SourceString:
    """``string SOURCE [PATH] [START] [END]``."""

    source: DataTarget
    path: NbtPath | None
    start: int | None
    end: int | None
    loc: Loc


DataSource = Union[SourceValue, SourceFrom, SourceString]


@node
class DataModify(Command):
    """``mode`` is set, append, prepend, insert (with ``index``) or merge."""

    target: DataTarget
    path: NbtPath
    mode: str
    index: int | None
    source: DataSource


@node
class DataRemove(Command):
    target: DataTarget
    path: NbtPath


# entities
@node
class TagCommand(Command):
    """``tag TARGETS add|remove NAME`` or ``tag TARGETS list`` (``name`` None)."""

    targets: Target
    action: str
    name: str | None


@node
class Summon(Command):
    entity_type: str
    pos: Vec3 | None
    nbt: Compound | None


@node
class Kill(Command):
    targets: Target | None  # None: the executor


@node
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
@node
class Gamerule(Command):
    rule: str
    value: str | None  # None: query


@node
class RandomCommand(Command):
    """``random value|roll RANGE [SEQUENCE]`` or ``random reset SEQUENCE|* [SEED [INCLUDE_WORLD INCLUDE_SEQ]]``."""

    action: str
    range: IntRange | None
    sequence: str | None
    seed: int | None = None
    include_world_seed: bool = True
    include_sequence_id: bool = True


@node
class Time(Command):
    """``time add|set|query``; ``value`` in ticks for add/set (``day``, ``night`` ... converted)."""

    action: str
    value: int | None
    query: str | None  # "daytime" | "gametime" | "day"


@node
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


@node
class Ride(Command):
    """``ride TARGET mount VEHICLE`` or ``ride TARGET dismount`` (1.19.4+)."""

    target: Target
    action: str  # "mount" | "dismount"
    vehicle: Target | None = None


@node
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


@node
class Trigger(Command):
    objective: str
    action: str | None  # None (increment by 1), "add", "set"
    value: int | None


@node
class Say(Command):
    message: str


@node
class Tellraw(Command):
    targets: Target
    text: str  # JSON/SNBT text component, as written


# ----------------------------------------------------------------------------- PackTest's commands

@node
class PackTestAssert(Command):
    """PackTest's ``assert [not] CONDITION`` run by a function (not a test file's step):
    ``condition`` is an ``execute if`` test, None for PackTest's own ``chat`` and ``entity ... inside``
    (``text`` keeps the condition as written)."""

    negated: bool
    condition: Condition | None
    text: str


@node
class PackTestFail(Command):
    """PackTest's ``fail MESSAGE`` run by a function."""

    message: str  # text component, as written


@node
class PackTestSucceed(Command):
    """PackTest's ``succeed`` run by a function."""


# ----------------------------------------------------------------------------- files and packs


@node
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


@node
class ItemArgument:
    """An item to create (ItemArgument): ``id[component=value,!component]`` from 1.20.5, ``id{tag}``
    before. ``components`` are (namespaced component id, SNBT value) in the order written;
    ``removed`` the ``!component`` ids; ``tag`` the older NBT form (None when absent)."""

    loc: Loc
    id: str
    components: tuple[tuple[str, Any], ...] = ()
    removed: tuple[str, ...] = ()
    tag: Compound | None = None


@node
class ComponentTest:
    """One test inside an item predicate's brackets: ``component`` (exists), ``component=value``
    (the component equals the value), ``predicate~value`` (a sub-predicate); ``count`` with either
    takes an int or ``{min, max}``;
    ``negated`` for a leading ``!``."""

    name: str
    kind: str  # "exists", "=", "~"
    value: Any = None
    negated: bool = False


@node
class ItemPredicate:
    """ItemPredicateArgument: ``id``, ``#tag`` or ``*`` (``id`` None), then ``[...]`` tests (from
    1.20.5: a tuple of any-of groups, all of which must pass) or ``{nbt}`` (older: a partial match
    of the stack's ``tag``)."""

    loc: Loc
    id: str | None
    is_tag: bool = False
    tests: tuple[tuple[ComponentTest, ...], ...] = ()
    tag: Compound | None = None


@node
class SlotArgument:
    """A slot name (SlotArgument / SlotsArgument) and the slot ids it names (several for a range
    such as ``container.*``)."""

    name: str
    ids: tuple[int, ...]


@node
class ItemTarget:
    """Where items go or come from: ``entity TARGETS`` or ``block POS``."""

    kind: str  # "entity" or "block"
    target: Target | Vec3  # a selector/name for entities, a position for blocks


@node
class ResourceOrInline:
    """ResourceOrIdArgument: a loot table / item modifier / predicate id, or (from 1.20.5) an
    inline definition written as SNBT; ``inline`` holds its NBT, which the codecs read as JSON
    (NbtOps: a compound is an object, a typed number a number) while the fields that take NBT
    (custom data, components) keep its types."""

    id: str | None
    inline: Any = None
    text: str = ""


@node
class Give(Command):
    targets: Target
    item: ItemArgument
    count: int = 1


@node
class Clear(Command):
    targets: Target | None = None  # None: the executor
    item: ItemPredicate | None = None
    max_count: int | None = None


@node
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


@node
class ItemModify(Command):
    target: ItemTarget
    slot: SlotArgument
    modifier: ResourceOrInline


@node
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
