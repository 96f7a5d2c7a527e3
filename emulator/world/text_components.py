"""``tellraw`` and ``say``: the receivers and the text as the game resolves it for them.

Source (decompiled 1.21): server/commands/TellRawCommand.java (EntityArgument.getPlayers: no
player fails "No player was found"; each receiver gets ComponentUtils.updateForEntity(source,
component, player, 0); the result is the number of receivers), network/chat/ComponentUtils
(updateForEntity resolves every contents part and keeps the style and the ``extra`` siblings),
contents/ScoreContents (a selector name must find exactly one entity, ``*`` is the receiver; an
unset score or unknown objective reads as empty), contents/SelectorContents (the display names
joined with ", "), contents/NbtContents (``storage``/``entity`` values as text, joined with ", ";
with ``interpret: true`` each value read as a component and resolved in turn).

The log keeps one line per command: the component as written when nothing in it needs resolving,
else the resolved component as compact JSON (``*`` in a score name resolved for the first
receiver). SNBT components (1.21.5+) are read as SNBT.

``say``: MessageArgument replaces each selector in the message by the display names it finds,
joined with ", " (EntitySelector.joinNames; nothing found leaves nothing).
"""
from __future__ import annotations

import json
import re
from typing import Callable

from emulator.world.state import WorldState
from emulator.world import nbt_ops
from emulator.world.entities import Entity, entity_nbt
from emulator.world.errors import CommandFailure
from emulator.world.teams import formatted_name
from emulator.world.nbt_ops import tag_as_string
from emulator.world.text import RESOLVED, needs_resolving, plain_text, plain_value, read_component
from mcfunction_parser import ast
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.nbt import Compound
from mcfunction_parser.nbt_path import nbt_path
from mcfunction_parser.reader import ParseError, Reader
from mcfunction_parser.selectors import selector

_MESSAGE_SELECTOR = re.compile(r"@[spaern]")
_CONTENT_KEYS = RESOLVED + ("separator", "storage", "entity", "block", "interpret", "source")
Select = Callable[[str], list[Entity]]  # a selector or name as written -> the entities it finds


def finder(parse: Callable[[str], object], select: Callable[[object], list[Entity]]) -> Select:
    """A :data:`Select` from a backend's target parser and selector evaluation (a malformed
    selector inside a text finds nothing)."""
    def find(text: str) -> list[Entity]:
        try:
            target = parse(text)
        except ValueError:
            return []
        return select(target)

    return find


def say_text(message: str, select: Callable[[ast.Selector], list[Entity]]) -> str:
    """The message of ``say`` with its selectors replaced by the names they find."""
    parts, pos = [], 0
    for match in _MESSAGE_SELECTOR.finditer(message):
        if match.start() < pos:
            continue
        reader = Reader(message, Loc("<message>", 1, 1), (1, 21, 0))
        reader.pos = match.start()
        try:
            found = select(selector(reader))
        except ParseError:  # the parser checked the message: not a selector here
            continue
        parts += [message[pos:match.start()], ", ".join(e.display_name for e in found)]
        pos = reader.pos
    return "".join(parts) + message[pos:]


def tellraw_command(state: WorldState, cmd: ast.Tellraw, receivers: list[Entity], select: Select) -> int:
    """Log the line for ``receivers`` (what the targets found); fails when none is a player.
    TellRawCommand resolves the text for each player in turn (a ``*`` score is the receiver's):
    one log entry per distinct text, with the players who got it; when resolving fails for a
    player, the players before it have their message."""
    players = [e for e in receivers if e.is_player]
    if not players:
        raise CommandFailure("argument.entity.notfound.player")
    sent: dict[str, list[str]] = {}  # text -> receivers, in the order first sent
    try:
        for player in players:
            sent.setdefault(resolved_text(cmd.text, state, select, player), []).append(player.uuid_string)
    finally:
        for text, uuids in sent.items():
            state.emit("tellraw", text, cmd.loc, tuple(uuids))
    return len(players)


def resolved_plain(text: str, state: WorldState, select: Select, receiver: Entity | None) -> str:
    """The plain text of a text component resolved for ``receiver`` (ComponentUtils.updateForEntity:
    a command's message argument read with getResolvedComponent, as PackTest's ``fail`` reads its
    message; ``receiver`` is the source's entity, None for the server)."""
    return plain_text(resolved_text(text, state, select, receiver), state.version)


def resolved_text(text: str, state: WorldState, select: Select, receiver: Entity | None) -> str:
    component = read_component(text)
    if component is None or not needs_resolving(component):
        return text
    resolved = _resolve(component, _Resolver(state, select, receiver))
    return json.dumps(resolved, ensure_ascii=False, separators=(",", ":"))


def _resolve(component, resolver: "_Resolver"):
    if isinstance(component, list):
        return [_resolve(c, resolver) for c in component]
    if not isinstance(component, dict):
        return component
    out = {k: v for k, v in component.items() if k not in _CONTENT_KEYS and k != "extra"}  # the style stays
    interpreted = []
    if "score" in component:
        out["text"] = resolver.score(component["score"])
    elif "selector" in component:
        out = _selector(component, resolver, out)
    elif "nbt" in component and component.get("interpret") in (True, 1):
        out["text"], interpreted = "", resolver.interpreted(component)  # the values come first
    elif "nbt" in component:
        out["text"] = resolver.nbt(component)
    if isinstance(component.get("with"), list):  # TranslatableContents.resolve: each argument
        out["with"] = [_resolve(argument, resolver) for argument in component["with"]]
    if "extra" in component or interpreted:
        out["extra"] = out.get("extra", []) + interpreted + _resolve(component.get("extra", []), resolver)
    return out


DEFAULT_SEPARATOR = {"text": ", ", "color": "gray"}  # ComponentUtils.DEFAULT_SEPARATOR


def _selector(component: dict, resolver: "_Resolver", style: dict) -> dict:
    """SelectorContents.resolve: ComponentUtils.formatList of the display names it finds (one name
    as it is, several joined by the separator, none empty), then the written style applied over
    it (MutableComponent.withStyle: what the component sets wins)."""
    names = [display_name(e, resolver.state.version, resolver.state.teams) for e in resolver.select(str(component["selector"]))]
    if len(names) == 1:
        found = names[0]
    else:
        separator = component.get("separator", DEFAULT_SEPARATOR)
        joined = [part for i, name in enumerate(names) for part in ([separator] if i else []) + [name]]
        found = {"text": "", "extra": joined} if joined else {"text": ""}
    return {**found, **style}


def display_name(entity: Entity, version, teams=None) -> dict:
    """Entity.getDisplayName as a component: the name (its custom name, a player's name, else the
    type's name) with a ``show_entity`` hover event and the UUID string to insert; a player's
    inserts its name and suggests ``/tell NAME `` on click (Player.decorateDisplayNameComponent).
    Before 1.21.5 the events are written ``hoverEvent``/``clickEvent`` with the old fields. In a
    team, the name is its prefix, name and suffix in the team's colour (PlayerTeam.formatNameForTeam),
    the events on that whole."""
    written = read_component(entity.custom_name) if entity.custom_name is not None and not entity.is_player else None
    if isinstance(written, dict):
        name = dict(written)
    elif isinstance(written, list):
        name = {"text": "", "extra": written}
    else:
        name = {"text": entity.display_name}
    if teams is not None and entity.team is not None and entity.team in teams.teams:
        name = formatted_name(teams.teams[entity.team], name)
    tooltip = {"text": entity.display_name}
    new = tuple(version) >= (1, 21, 5)
    if new:
        name["hover_event"] = {"action": "show_entity", "id": entity.type, "uuid": entity.uuid_string, "name": tooltip}
    else:
        name["hoverEvent"] = {"action": "show_entity",
                              "contents": {"type": entity.type, "id": entity.uuid_string, "name": tooltip}}
    if entity.is_player:
        command = f"/tell {entity.player_name} "
        name["click_event" if new else "clickEvent"] = ({"action": "suggest_command", "command": command} if new
                                                         else {"action": "suggest_command", "value": command})
        name["insertion"] = entity.player_name
    else:
        name["insertion"] = entity.uuid_string
    return name


class _Resolver:
    def __init__(self, state: WorldState, select: Select, receiver: Entity) -> None:
        self.state, self.select, self.receiver = state, select, receiver

    def score(self, score: dict) -> str:
        """ScoreContents.resolve: the holder (one entity for a selector, the receiver for ``*``)."""
        name = str(score.get("name", ""))
        if name == "*":
            if self.receiver is None:  # resolved for no entity (the server): nothing
                return ""
            holder = self.receiver.score_holder
        elif name.startswith("@"):
            found = self.select(name)
            if len(found) != 1:
                raise CommandFailure("argument.entity.toomany")
            holder = found[0].score_holder
        else:
            holder = name
        value = self.state.scoreboard.get(holder, str(score.get("objective", "")))
        return "" if value is None else str(value)

    def _values(self, component: dict) -> list:
        """NbtContents: the values at the path in the storage or the entities."""
        try:
            path = nbt_path(Reader(str(component["nbt"]), Loc("<text>", 1, 1), (1, 21, 0)))
        except ParseError:
            return []
        if "storage" in component:
            roots = [self.state.storage.get(str(component["storage"]), Compound())]
        elif "entity" in component:
            roots = [entity_nbt(e) for e in self.select(str(component["entity"]))]
        else:
            return []  # block entities are not modelled
        values = []
        for root in roots:
            try:
                values += nbt_ops.get(root, path)
            except CommandFailure:
                continue
        return values

    def nbt(self, component: dict) -> str:
        """The values as text, joined with ", "."""
        return ", ".join(tag_as_string(v) for v in self._values(component))

    def interpreted(self, component: dict) -> list:
        """``interpret: true``: each value read as a text component, resolved in turn, joined with
        the separator (default ", "). Before 1.21.5 a value's string is parsed as JSON (a value that
        is not a component reads as nothing); from 1.21.5 the tag itself is the component
        (ComponentSerialization.CODEC over NbtOps: a string tag is plain text)."""
        parts = []
        for value in self._values(component):
            if self.state.version >= (1, 21, 5):
                read = plain_value(value)
            else:
                try:
                    read = json.loads(tag_as_string(value))
                except ValueError:
                    continue
            if parts:
                parts.append(component.get("separator", ", "))
            parts.append(_resolve(read, self))
        return parts
