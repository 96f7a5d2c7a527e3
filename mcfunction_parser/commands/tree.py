"""Commands without a parser of their own, checked against the game's command tree for the target
release (:func:`..gamedata.command_tree`); the AST keeps them as text (GenericCommand).

The walk follows Brigadier's CommandDispatcher.parseNodes: after a space, a word that names a
literal child is only that literal (getRelevantNodes), otherwise every argument child is tried in
order; the first branch that reads the whole command and ends on an executable node wins. When
none does, the error that got furthest is reported, at the argument it is about.
"""
from __future__ import annotations

import re

from .. import game_objects as objects
from .. import gamedata, items, particles, snbt
from ..arguments import duration, objective, score_holder, single_score_holder, text_component, vec2, vec3
from ..ast import GenericCommand
from ..features import version_text
from ..nbt_path import nbt_path
from ..primitives import float_range, int_range, is_uuid, resource_location, resource_or_tag
from ..reader import WORD, ParseError, Reader, show
from ..selectors import target
from .chat import message
from .scoreboard import OPERATIONS, criterion, display_slot

_TREES: dict = {}  # version -> root node, or None when no tree is known
# (command text, version) -> its warnings as (message, offset from the command's start): whether a
# command is valid depends on nothing else, and packs repeat commands (the same sound, the same fill)
_VALID: dict[tuple[str, tuple], tuple] = {}
_VALID_MAX = 8192


def root_for(version) -> dict | None:
    """The command tree of ``version``; None when there is none (``dpemu check`` reports that once)."""
    if version not in _TREES:
        try:
            _TREES[version] = gamedata.command_tree(version)
        except gamedata.GameDataMissing:
            _TREES[version] = None
    return _TREES[version]


def tree_command(r: Reader, loc, name: str) -> GenericCommand:
    """``name``'s arguments (the cursor after the name) walked through the tree; kept as text."""
    start = r.pos - len(name)
    text = r.text[start:]
    key = (text, r.version)
    known = _VALID.get(key)
    if known is None:
        root = root_for(r.version)
        node = root["children"].get(name) if root is not None else None
        before = len(r.warnings)
        if node is not None:
            _walk(r, root, node)
        known = tuple((message, pos - start) for message, pos in r.warnings[before:])
        del r.warnings[before:]
        if len(_VALID) >= _VALID_MAX:
            _VALID.clear()
        _VALID[key] = known
    r.warnings.extend((message, pos + start) for message, pos in known)
    r.pos = r.end
    return GenericCommand.new(loc, name, text)


def _walk(r: Reader, root: dict, node: dict) -> None:
    """The walk; against another minor release's tree (1.13 – 1.15 use 1.16.5's), a problem is a
    warning: the syntax may have changed between them (1.13's ``locate Village``)."""
    stand_in = _stand_in(r.version)
    if stand_in is None:
        _rest(r, _target(root, node), root)
        return
    try:
        _rest(r, _target(root, node), root)
    except ParseError as error:
        r.warnings.append((f"{error.message} ({stand_in_note(r.version)})", error.pos))


def _stand_in(version) -> tuple | None:
    """The release whose tree checks ``version`` when it is of another minor release, else None."""
    release = gamedata.tree_release(version)
    return release if release[:2] != version[:2] else None


def newer_than_every_tree(version) -> bool:
    """A release after the newest command tree dpemu has (26.x): its syntax may have changed in
    ways no reader here knows (``time of <clock>``)."""
    stand_in = _stand_in(version)
    return stand_in is not None and version > stand_in


def stand_in_note(version) -> str:
    return (f"checked against the {version_text(_stand_in(version))} command tree: "
            f"dpemu has none for {version_text(version)}")


def _target(root: dict, node: dict) -> dict:
    """A node's redirect target (``tell`` -> ``msg``), or the node itself."""
    path = node.get("redirect")
    if not path:
        return node
    for step in path:
        root = root["children"][step]
    return root


def _expected(children: dict) -> str:
    names = [name if child["type"] == "literal" else f"<{name}>" for name, child in children.items()]
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " or " + names[-1]


def _rest(r: Reader, node: dict, root: dict) -> None:
    """What follows ``node`` (its text read up to r.pos) must match one of its children."""
    pos = r.pos
    children = node.get("children")
    if pos >= r.end:
        if node.get("executable") or not children:
            return
        r.fail(f"incomplete command: expected {_expected(children)}")
    if r.text[pos] != " ":
        r.fail(f"expected whitespace to end the argument, got {r.found()}")
    if not children:
        r.pos = pos + 1
        extra = r.rest_word()
        r.fail(f"expected end of command, got {show(extra)}" if extra else
               "unexpected space: arguments are separated by exactly one space", pos + 1 if extra else pos)
    start = pos + 1
    word = WORD.match(r.text, start).group()
    literal = children.get(word)
    if literal is not None and literal["type"] == "literal":
        r.pos = start + len(word)
        _rest(r, _target(root, literal), root)
        return
    arguments = [child for child in children.values() if child["type"] == "argument"]
    if not arguments:
        r.pos = start
        r.fail(f"expected {_expected(children)}, got {show(word) if word else r.found()}", start)
    best: ParseError | None = None
    for child in arguments:
        r.pos = start
        try:
            _argument(r, child)
            _rest(r, _target(root, child), root)
            return
        except ParseError as error:
            if best is None or error.pos > best.pos:
                best = error
    raise best


def _argument(r: Reader, node: dict) -> None:
    parser = node["parser"]
    if (r.pos >= r.end or r.text[r.pos] == " ") and not _takes_all(node):
        r.fail(f"expected an argument, got {r.found()}")
    reader = ARGUMENTS.get(parser)
    if reader is None:  # a parser this table doesn't know yet: one word
        r.word()
        return
    reader(r, node.get("properties") or {})


def _takes_all(node: dict) -> bool:
    """Arguments that read the rest of the command as it is, a leading space included."""
    return node["parser"] == "minecraft:message" or (node.get("properties") or {}).get("type") == "greedy"


# ----------------------------------------------------------------------------- argument types
# Each reads one argument at the cursor (Brigadier's ArgumentType.parse) or fails there.

def _number(r: Reader, props: dict, integer: bool) -> None:
    lo, hi = props.get("min"), props.get("max")
    if integer:
        r.integer(**({"lo": lo} if lo is not None else {}), **({"hi": hi} if hi is not None else {}))
    else:
        r.double(lo, hi)


def _long(r: Reader, props: dict) -> None:
    start = r.pos
    token = re.match(r"[0-9.\-]*", r.text[start:]).group()
    if not re.fullmatch(r"-?[0-9]+", token) or not -2**63 <= int(token) < 2**63:
        r.fail(f"invalid long '{token}'" if token else f"expected a long, got {r.found()}", start)
    r.pos += len(token)


def _string(r: Reader, props: dict) -> None:
    kind = props.get("type", "word")
    if kind == "greedy":  # StringArgumentType.greedyString: the rest, spaces and all
        r.pos = r.end
    elif kind == "phrase":
        r.string()
    else:
        r.unquoted()


def _choice(*words: str, what: str):
    choices = frozenset(words)

    def read(r: Reader, props: dict) -> None:
        r.literal(choices, what)
    return read


def _entity(r: Reader, props: dict) -> None:
    target(r, single=props.get("amount") == "single", players=props.get("type") == "players")


def _game_profile(r: Reader, props: dict) -> None:
    """GameProfileArgument: a selector of players only (ERROR_ONLY_PLAYERS_ALLOWED), or a name."""
    target(r, players=True) if r.peek() == "@" else r.word()


def _score_holder(r: Reader, props: dict) -> None:
    (single_score_holder if props.get("amount") == "single" else score_holder)(r)


def _angle(r: Reader, props: dict) -> None:
    start = r.pos
    if r.peek() == "~":
        r.pos += 1
        if r.pos >= r.end or r.text[r.pos] == " ":
            return
    if r.peek() == "^":
        r.fail("local coordinates (^) are not allowed here", start)
    r.double(what="angle")


def _uuid(r: Reader, props: dict) -> None:
    start = r.pos
    word = r.word()
    if not is_uuid(word):
        r.fail(f"invalid UUID {show(word)}", start)


def _swizzle(r: Reader, props: dict) -> None:
    start = r.pos
    word = r.word()
    if not re.fullmatch(r"[xyz]{1,3}", word) or len(set(word)) != len(word):
        r.fail(f"invalid swizzle {show(word)}: expected a combination of x, y and z", start)


def _hex_color(r: Reader, props: dict) -> None:
    start = r.pos
    word = r.word()
    if not re.fullmatch(r"[0-9A-Fa-f]{6}", word):
        r.fail(f"invalid hex color {show(word)}: expected 6 hexadecimal digits", start)


_COLORS = ("black", "dark_blue", "dark_green", "dark_aqua", "dark_red", "dark_purple", "gold", "gray",
           "dark_gray", "blue", "green", "aqua", "red", "light_purple", "yellow", "white", "reset")
_EQUIPMENT = ("mainhand", "offhand", "head", "chest", "legs", "feet", "body", "saddle")
def _registry_resource(r: Reader, props: dict) -> None:
    objects.registry_id(r, props.get("registry", "").removeprefix("minecraft:"))


def _resource_or_tag(r: Reader, props: dict) -> None:
    start = r.pos
    rid, tag = resource_or_tag(r, "resource")
    if not tag:
        objects.check_id(r, props.get("registry", "").removeprefix("minecraft:"), rid, start)


def _id_or_inline(r: Reader, props: dict) -> None:
    """ResourceOrIdArgument (loot tables, predicates, modifiers, dialogs, 1.20.5+): an id or an
    inline SNBT definition."""
    if r.peek() in "{[":
        snbt.value(r)
    else:
        resource_location(r)


def _resource_selector(r: Reader, props: dict) -> None:
    """ResourceSelectorArgument: an id pattern with ``*`` and ``?``."""
    start = r.pos
    word = WORD.match(r.text, start).group()
    if not re.fullmatch(r"[0-9a-z_:/.\-*?]+", word):
        r.fail(f"invalid resource pattern {show(word)}", start)
    r.pos += len(word)


def _message(r: Reader, props: dict) -> None:
    message(r)


def _objective(r: Reader, props: dict) -> None:
    objective(r)


def _team(r: Reader, props: dict) -> None:
    start = r.pos
    if not r.unquoted():
        r.fail(f"expected a team name, got {r.found()}", start)


def _operation(r: Reader, props: dict) -> None:
    start = r.pos
    word = r.word()
    if word not in OPERATIONS:
        r.fail(f"invalid operation {show(word)}", start)


def _time(r: Reader, props: dict) -> None:
    duration(r, props.get("min", 0))  # TimeArgument.time(min): 26.1's time add takes a negative time


def _function(r: Reader, props: dict) -> None:
    resource_or_tag(r, "function")


ARGUMENTS = {
    "brigadier:bool": lambda r, p: r.boolean(),
    "brigadier:integer": lambda r, p: _number(r, p, True),
    "brigadier:float": lambda r, p: _number(r, p, False),
    "brigadier:double": lambda r, p: _number(r, p, False),
    "brigadier:long": _long,
    "brigadier:string": _string,
    "minecraft:angle": _angle,
    "minecraft:block_pos": lambda r, p: vec3(r, block=True),
    "minecraft:block_predicate": lambda r, p: objects.block(r, True),
    "minecraft:block_state": lambda r, p: objects.block(r, False),
    "minecraft:color": _choice(*_COLORS, what="color"),
    "minecraft:column_pos": lambda r, p: vec2(r, integers=True),
    "minecraft:component": lambda r, p: text_component(r),
    "minecraft:dialog": _id_or_inline,
    "minecraft:dimension": lambda r, p: resource_location(r, "dimension"),
    "minecraft:entity": _entity,
    "minecraft:entity_anchor": _choice("eyes", "feet", what="anchor"),
    "minecraft:entity_summon": lambda r, p: objects.registry_id(r, "entity_type"),
    "minecraft:float_range": lambda r, p: float_range(r),
    "minecraft:function": _function,
    "minecraft:game_profile": _game_profile,
    "minecraft:gamemode": _choice("survival", "creative", "adventure", "spectator", what="game mode"),
    "minecraft:heightmap": _choice("world_surface", "motion_blocking", "motion_blocking_no_leaves", "ocean_floor",
                                   what="heightmap"),
    "minecraft:hex_color": _hex_color,
    "minecraft:int_range": lambda r, p: int_range(r),
    "minecraft:item_enchantment": lambda r, p: objects.registry_id(r, "enchantment"),
    "minecraft:item_predicate": lambda r, p: items.item_predicate(r),
    "minecraft:item_slot": lambda r, p: items.slot(r),
    "minecraft:item_slots": lambda r, p: items.slot(r, ranges=True),
    "minecraft:item_stack": lambda r, p: items.item_argument(r),
    "minecraft:loot_modifier": _id_or_inline,
    "minecraft:loot_predicate": _id_or_inline,
    "minecraft:loot_table": _id_or_inline,
    "minecraft:message": _message,
    "minecraft:mob_effect": lambda r, p: objects.registry_id(r, "mob_effect"),
    "minecraft:nbt_compound_tag": lambda r, p: snbt.compound(r),
    "minecraft:nbt_path": lambda r, p: nbt_path(r),
    "minecraft:nbt_tag": lambda r, p: snbt.value(r),
    "minecraft:objective": _objective,
    "minecraft:objective_criteria": lambda r, p: criterion(r),
    "minecraft:operation": _operation,
    "minecraft:particle": lambda r, p: particles.particle(r),
    "minecraft:resource": _registry_resource,
    "minecraft:resource_key": lambda r, p: resource_location(r),
    "minecraft:resource_location": lambda r, p: resource_location(r),
    "minecraft:resource_or_tag": _resource_or_tag,
    "minecraft:resource_or_tag_key": lambda r, p: resource_or_tag(r, "resource"),
    "minecraft:resource_selector": _resource_selector,
    "minecraft:rotation": lambda r, p: vec2(r),
    "minecraft:score_holder": _score_holder,
    "minecraft:scoreboard_slot": lambda r, p: display_slot(r),
    "minecraft:style": lambda r, p: text_component(r),
    "minecraft:swizzle": _swizzle,
    "minecraft:team": _team,
    "minecraft:template_mirror": _choice("none", "front_back", "left_right", what="mirror"),
    "minecraft:template_rotation": _choice("none", "clockwise_90", "counterclockwise_90", "180", what="rotation"),
    "minecraft:time": _time,
    "minecraft:uuid": _uuid,
    "minecraft:vec2": lambda r, p: vec2(r),
    "minecraft:vec3": lambda r, p: vec3(r),
}
