"""Signs (standing, wall, hanging and wall hanging): their block entity and a player's click on one.

- ``is_sign(block_id)``.
- ``new_entity(version)``: SignBlockEntity.saveAdditional of a new sign (both sides' four empty
  lines, black, not glowing, not waxed).
- ``loaded_entity(version, written)``: the sign a ``setblock``/``fill``/structure with NBT leaves
  (SignBlockEntity.loadAdditional over a new sign): ``front_text``/``back_text`` replace a side when
  they decode (SignText.DIRECT_CODEC: exactly four ``messages``, ``color`` black and
  ``has_glowing_text`` false by default, ``filtered_messages`` kept only where they differ),
  ``is_waxed`` read as a boolean. A line that is a plain text alone is saved as its string
  (ComponentSerialization: tryCollapseToString); a line that needs resolving (score, selector,
  nbt: loadLine's ComponentUtils.updateForEntity) is not modelled.
- ``use(state, player, pos, block)``: SignBlock.useWithoutItem: the run_command click events of
  the side the player faces run as the player at the sign's centre with permission 2
  (executeClickCommandsIfPresent); a waxed sign, one whose commands ran or one whose text the
  player may edit consumes the use (the editor the game opens is not observable by a pack).

Sources (decompiled 1.21): world/level/block/entity/SignBlockEntity.java, SignText.java,
world/level/block/SignBlock.java (useWithoutItem, useItemOn: dyes, ink sacs and honeycomb
apply to the text), StandingSignBlock / CeilingHangingSignBlock (rotation x 22.5 degrees),
WallSignBlock (facing, its hitbox centre), WallHangingSignBlock, util/Mth (atan2,
degreesDifferenceAbs).
"""
from __future__ import annotations

import json

import numpy as np

from emulator.world import mth
from emulator.world.errors import Unmodelled
from emulator.world.text import RESOLVED, needs_resolving, plain_value
from mcfunction_parser.nbt import Byte, Compound, List, String

SNBT_TEXT_VERSION = (1, 21, 5)  # messages are components as NBT from 1.21.5, JSON strings before
_COLOURS = frozenset("white orange magenta light_blue yellow lime pink gray light_gray cyan purple blue brown green "
                     "red black".split())
# SignApplicator items (DyeItem, GlowInkSacItem, InkSacItem, HoneycombItem)
APPLICATORS = frozenset({"minecraft:glow_ink_sac", "minecraft:ink_sac", "minecraft:honeycomb"}) | frozenset(
    f"minecraft:{c}_dye" for c in _COLOURS)
# WallSignBlock's shape per facing: its centre's x and z within the block
_WALL_CENTRES = {"north": (0.5, 0.9375), "south": (0.5, 0.0625), "east": (0.0625, 0.5), "west": (0.9375, 0.5)}
_Y_ROT = {"south": 0.0, "west": 90.0, "north": 180.0, "east": 270.0}  # Direction.toYRot


def is_sign(block_id: str) -> bool:
    return block_id.endswith("_sign")


def _empty_line(version) -> String:
    """CommonComponents.EMPTY as saved: a component from 1.21.5, its JSON before (``""`` from 1.20.3,
    ``{"text":""}`` before)."""
    return String("" if version >= SNBT_TEXT_VERSION else '""' if version >= (1, 20, 3) else '{"text":""}')


def _side(messages, color: str = "black", glowing: bool = False) -> Compound:
    return Compound(messages=List(messages), color=String(color), has_glowing_text=Byte(int(glowing)))


def new_entity(version) -> Compound:
    version = tuple(version)
    if version < (1, 20, 0):
        raise Unmodelled("a sign's block entity before 1.20 (Text1 .. Text4)")
    return Compound(front_text=_side([_empty_line(version)] * 4), back_text=_side([_empty_line(version)] * 4),
                    is_waxed=Byte(0))


def loaded_entity(version, written: Compound | None) -> Compound:
    version = tuple(version)
    sign = new_entity(version)
    if written is None:
        return sign
    for key in ("front_text", "back_text"):
        side = written.get(key)
        decoded = _decoded_side(version, side) if isinstance(side, Compound) else None
        if decoded is not None:
            sign[key] = decoded
    waxed = written.get("is_waxed")
    sign["is_waxed"] = Byte(1 if waxed is not None and not isinstance(waxed, (str, Compound, List)) and int(waxed) else 0)
    return sign


def _decoded_side(version, side: Compound) -> Compound | None:
    """SignText.DIRECT_CODEC.parse, then encoded again; None where it does not decode (the game logs
    the error and the side stays as it was)."""
    lines = _lines(version, side.get("messages"))
    if lines is None:
        return None
    filtered = _lines(version, side.get("filtered_messages"))  # lenient: a bad one is left out
    color = side.get("color", String("black"))
    glowing = side.get("has_glowing_text", Byte(0))
    if not isinstance(color, str) or str(color) not in _COLOURS:
        color = String("black")  # fieldOf(...).orElse(BLACK)
    decoded = _side(lines, str(color), not isinstance(glowing, (str, Compound, List)) and bool(int(glowing)))
    if filtered is not None and [str(f) for f in filtered] != [str(m) for m in lines]:
        decoded["filtered_messages"] = List(filtered)
    return decoded


def _lines(version, messages) -> list | None:
    if not isinstance(messages, List) or len(messages) != 4:
        return None
    lines = []
    for message in messages:
        component = _component(version, message)
        if component is _INVALID:
            return None
        if needs_resolving(component):
            raise Unmodelled("a sign line with a score, selector or nbt component (resolved when the sign loads)")
        lines.append(_saved_line(version, message, component))
    return lines


_INVALID = object()


def _component(version, tag):
    """A line as plain values (dicts, lists, strings), or _INVALID."""
    if version >= SNBT_TEXT_VERSION:
        return plain_value(tag) if isinstance(tag, (str, Compound, List)) else _INVALID
    if not isinstance(tag, str):
        return _INVALID
    try:
        return json.loads(str(tag))
    except ValueError:
        return _INVALID


def _saved_line(version, written, component):
    """A plain text alone collapses to its string (ComponentSerialization's codec: tryCollapseToString);
    anything else is kept as written."""
    text = None
    if isinstance(component, str):
        text = component
    elif isinstance(component, dict) and set(component) <= {"text", "type"} and component.get("type", "text") == "text":
        text = component.get("text")
    if not isinstance(text, str):
        return written
    return String(text) if version >= SNBT_TEXT_VERSION else String(json.dumps(text, ensure_ascii=False))


# ---------------------------------------------------------------------- a click on a sign
def _facing_front(block, pos, player) -> bool:
    """SignBlockEntity.isFacingFrontText: the player within 90 degrees of the sign's front."""
    properties = dict(block.properties)
    if "rotation" in properties:  # StandingSignBlock, CeilingHangingSignBlock: RotationSegment.convertToDegrees
        yaw, centre = np.float32(int(properties["rotation"]) * 22.5), (0.5, 0.5)
    else:
        facing = properties.get("facing", "north")
        yaw = np.float32(_Y_ROT[facing])
        centre = _WALL_CENTRES[facing] if "hanging" not in block.id else (0.5, 0.5)
    dx = float(player.pos[0]) - (pos[0] + centre[0])
    dz = float(player.pos[2]) - (pos[2] + centre[1])
    towards = np.float32(np.float32(mth.atan2(dz, dx) * 180.0 / float(np.float32(np.pi))) - np.float32(90.0))
    return abs(float(mth.wrap_degrees_f(towards - yaw))) <= 90.0


def _click_commands(version, side: Compound) -> list[str]:
    """The run_command click events of a side's lines (their own style, not their siblings')."""
    commands = []
    for message in side.get("messages", List()):
        component = _component(version, message)
        if not isinstance(component, dict):
            continue
        if version >= SNBT_TEXT_VERSION:
            event = component.get("click_event")
            command = event.get("command") if isinstance(event, dict) else None
        else:
            event = component.get("clickEvent")
            command = event.get("value") if isinstance(event, dict) else None
        if isinstance(event, dict) and event.get("action") == "run_command" and isinstance(command, str):
            commands.append(command)
    return commands


def use(state, player, pos, block, run) -> str:
    """SignBlock.useWithoutItem; ``run(state, command, player, pos)`` runs one click command."""
    sign = state.blocks.entity(pos)
    if sign is None:
        return "pass"
    side = sign.get("front_text" if _facing_front(block, pos, player) else "back_text")
    commands = _click_commands(tuple(state.version), side) if isinstance(side, Compound) else []
    for command in commands:
        run(state, command, player, pos)
    if int(sign.get("is_waxed", Byte(0))) or commands:
        return "consume"
    if player.gamemode == "adventure" or not _editable(tuple(state.version), side):
        return "pass"  # Player.mayBuild, SignBlock.hasEditableText
    return "consume"  # the editor opens for the player (SignBlockEntity.setAllowedPlayerEditor, unsaved)


def _editable(version, side) -> bool:
    """SignBlock.hasEditableText: every line empty or plain text (no translation, score ...)."""
    if not isinstance(side, Compound):
        return True
    for message in side.get("messages", List()):
        component = _component(version, message)
        if isinstance(component, dict) and any(k in component for k in ("translate", "keybind") + RESOLVED):
            return False
    return True
