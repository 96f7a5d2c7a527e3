"""World clocks and timelines (26.1): the game's own, a pack's ``data/<ns>/world_clock`` and
``data/<ns>/timeline`` files, and the clocks and timelines functions name.

Sources (26.1.2, decompiled): a world clock is a registry entry without fields (WorldClock; the
game's are WorldClocks.OVERWORLD and THE_END); a dimension type names its default clock
(DimensionTypes.bootstrap: the overworld and its caves the overworld clock, the end the end clock,
the nether none). A timeline (Timeline.DIRECT_CODEC) reads one ``clock``, may repeat every
``period_ticks`` (a positive int) and names ``time_markers``: id -> ticks (a non-negative int) or
``{"ticks", "show_in_commands": false}``; with a period each marker's ticks lie in [0, period)
(Timeline.validateInternal), and a marker id is defined once per clock (Timeline.validateRegistry).
The game's timelines are Timelines.bootstrap's. ``time of <clock>`` and ``time query <timeline>``
name a registry entry (ResourceArgument.parse looks it up when the function loads): an unknown
one fails the line, and the game does not load the function.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from mcfunction_parser import ast
from mcfunction_parser.diagnostics import ERROR, Diagnostic
from mcfunction_parser.pack.text import JsonDocument

WORLD_CLOCKS = (26, 1, 0)  # the release that made time a set of world clocks
OVERWORLD = "minecraft:overworld"
THE_END = "minecraft:the_end"
VANILLA_CLOCKS = (OVERWORLD, THE_END)
# dimension (its type, as the game's dimensions have) -> its default clock; the nether has none
DEFAULT_CLOCKS = {OVERWORLD: OVERWORLD, "minecraft:overworld_caves": OVERWORLD, THE_END: THE_END}


@dataclass(frozen=True)
class Timeline:
    clock: str
    period: int | None  # None: the timeline never repeats
    markers: dict[str, tuple[int, bool]] = field(default_factory=dict)  # id -> (ticks, show_in_commands)


_DAY = 24000
VANILLA_TIMELINES = {  # Timelines.bootstrap (the tracks left out: the emulator reads no environment attribute)
    "minecraft:day": Timeline(OVERWORLD, _DAY, {
        "minecraft:day": (1000, True), "minecraft:noon": (6000, True), "minecraft:night": (13000, True),
        "minecraft:midnight": (18000, True), "minecraft:wake_up_from_sleep": (0, False),
        "minecraft:roll_village_siege": (18000, False)}),
    "minecraft:moon": Timeline(OVERWORLD, _DAY * 8),  # MoonPhase.COUNT phases of a day
    "minecraft:villager_schedule": Timeline(OVERWORLD, _DAY),
    "minecraft:early_game": Timeline(OVERWORLD, None),
}


@dataclass
class Clocks:
    """The world clocks and timelines the loaded packs run with (the game's, then the packs')."""

    clocks: tuple[str, ...] = VANILLA_CLOCKS
    timelines: dict[str, Timeline] = field(default_factory=lambda: dict(VANILLA_TIMELINES))

    def markers(self, clock: str) -> dict[str, tuple[int, int | None]]:
        """The time markers of ``clock``: id -> (ticks, period), from every timeline reading it
        (ServerClockManager.init registers each timeline's markers with its clock)."""
        return {marker: (ticks, timeline.period) for timeline in self.timelines.values() if timeline.clock == clock
                for marker, (ticks, _) in timeline.markers.items()}


def read_clocks(clock_files, timeline_docs, diagnostics: list[Diagnostic]) -> Clocks:
    """The clocks and timelines of the packs: ``clock_files`` the ids of their ``world_clock``
    files (already parsed as JSON objects), ``timeline_docs`` ``(id, JsonDocument)`` of their
    ``timeline`` files. A timeline the game's codec refuses is an error and left out."""
    loaded = Clocks(tuple(dict.fromkeys((*VANILLA_CLOCKS, *clock_files))))
    paths = {}
    for timeline_id, doc in timeline_docs:
        timeline = _timeline(doc, loaded.clocks, diagnostics)
        if timeline is not None:
            loaded.timelines[timeline_id] = timeline
            paths[timeline_id] = doc.path
    seen: dict[tuple[str, str], str] = {}
    for timeline_id, timeline in loaded.timelines.items():  # Timeline.validateRegistry
        for marker in timeline.markers:
            earlier = seen.setdefault((timeline.clock, marker), timeline_id)
            if earlier != timeline_id:
                diagnostics.append(Diagnostic(ERROR, f"timeline {timeline_id}: time marker {marker} is defined for "
                                              f"clock {timeline.clock} already (by {earlier})",
                                              paths.get(timeline_id, timeline_id)))
    return loaded


def _timeline(doc: JsonDocument, clocks: tuple[str, ...], diagnostics: list[Diagnostic]) -> Timeline | None:
    value = doc.value

    def refuse(message: str, near: str | None = None) -> None:
        diagnostics.append(doc.diagnostic(ERROR, f"timeline: {message}", doc.find_string(near) if near else -1))

    if not isinstance(value, dict):
        return refuse("expected a JSON object")
    clock = value.get("clock")
    if not isinstance(clock, str):
        return refuse("missing clock (a world clock's id)")
    clock = _full_id(clock)
    if clock not in clocks:
        return refuse(f"unknown world clock '{clock}'", "clock")
    period = value.get("period_ticks")
    if period is not None and (not _is_int(period) or period < 1):
        return refuse(f"period_ticks must be a positive integer, got {period!r}", "period_ticks")
    markers = {}
    for marker, info in (value.get("time_markers") or {}).items():
        ticks, shown = (info, False) if not isinstance(info, dict) else (info.get("ticks"), info.get("show_in_commands",
                                                                                                      False))
        if not _is_int(ticks) or ticks < 0 or not isinstance(shown, bool):
            return refuse(f"time marker {marker}: ticks must be a non-negative integer", marker)
        if period is not None and ticks >= period:
            return refuse(f"Time Marker {_full_id(marker)} must be in range [0; {period})", marker)
        markers[_full_id(marker)] = (ticks, shown)
    return Timeline(clock, period, markers)


def _is_int(value: Any) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def _full_id(rid: str) -> str:
    return rid if ":" in rid else "minecraft:" + rid


def unknown_references(function: ast.Function, clocks: Clocks, lines: list[str]) -> list[Diagnostic]:
    """The lines of ``function`` (its source ``lines``) that name a clock or timeline no registry
    holds: each fails to parse in the game, which then refuses the whole function."""
    found = []
    for command in function.commands:
        command = _final(command)
        if not isinstance(command, ast.ClockCommand):
            continue
        for rid, loc, registry, known in ((command.clock, command.clock_loc, "world_clock", clocks.clocks),
                                          (command.timeline, command.timeline_loc, "timeline", clocks.timelines)):
            if rid is not None and rid not in known:
                found.append(Diagnostic.at(ERROR, f"Can't find element '{rid}' of type 'minecraft:{registry}'", loc,
                                           lines[loc.line - 1] if loc.line <= len(lines) else None))
    return found


def _final(command: ast.Command) -> ast.Command:
    """The command an ``execute ... run`` or ``return run`` chain ends with."""
    while True:
        if isinstance(command, ast.Execute) and command.run is not None:
            command = command.run
        elif isinstance(command, ast.Return) and command.command is not None:
            command = command.command
        else:
            return command
