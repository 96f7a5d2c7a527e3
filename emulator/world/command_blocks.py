"""Command blocks: impulse, repeating and chain command blocks running their ``Command`` as the
game runs them, with the block entity fields a pack reads back (``SuccessCount``, ``LastOutput``,
``LastExecution``, ``conditionMet``, ``powered``, ``auto``).

- ``default_entity(block_id)``: the block entity a command block is placed with.
- ``after_change(state, dimension, positions)``: after ``setblock``/``fill`` changed ``positions``:
  a command block placed there loads (CommandBlockEntity.loadAdditional -> setAutomatic: ``auto``
  schedules its tick unless powered or a chain block), and each command block beside a changed
  block hears the change (CommandBlock.neighborChanged: powered by a neighbour's signal, an
  impulse or repeating one not ``auto`` schedules its tick in 1 tick).
- ``neighbours_of(blocks, positions, block_ids)``: the blocks of those ids beside any changed
  position (the ones that hear the change; crafters use it too).
- ``after_edit(state, dimension, pos, before)``: after ``data merge|modify block`` changed a command
  block's entity (loadAdditional: ``auto`` rising schedules the tick).
- The block tick (CommandBlock.tick): an impulse block runs once, a repeating one every tick while
  powered or ``auto``; a conditional one only when the block behind it (against its facing) is a
  command block whose ``SuccessCount`` is above 0; after it, the chain blocks it faces run in turn
  (CommandBlock.executeChain: powered or ``auto`` ones, a conditional one as above, the chain
  stopping at a block that did not run its command this game time, at most
  ``maxCommandChainLength`` steps).
- Running the command (BaseCommandBlock.performCommand): not twice in a game time (``LastExecution``
  with ``UpdateLastExecution``); ``SuccessCount`` the command's success (1 or 0); as a source at the
  block's centre, rotated to its facing (Direction.toYRot), in the block's level, with no entity. The
  runtime runs the text (``state.command_runner(text, context) -> int | None``: the successes, one
  per context the command ran in).

Power (Level.hasNeighborSignal) comes from a neighbouring redstone block, a powered lever or
button, or a lit redstone torch; any other redstone component beside a command block is not
modelled (a warning: the test is inconclusive). ``LastOutput`` (with ``TrackOutput``) is the last
message the command sent its source, after ``[HH:mm:ss] `` from the wall clock (:func:`feedback`:
``help``'s usage, ``function``'s ``Running function ID`` when the functions cannot return, none
from ``tellraw``, ``say`` and ``return N``); another command's message is
not produced (the time alone, and a warning: the test is inconclusive). ``SuccessCount`` counts a
success per context the command ran in, as the game's result callback (an ``execute`` whose stages
change the world, ``store`` or ``summon``, or with an ``if function`` stage, counts one). A command block in another level runs there (the
level's blocks, block ticks and the command's dimension). ``CustomName`` naming the source (``@`` by default) is not modelled.

Sources (decompiled 1.21.x and 26.1): world/level/block/CommandBlock.java (neighborChanged, tick,
execute, executeChain, setPoweredAndUpdate), block/entity/CommandBlockEntity.java (loadAdditional,
setAutomatic, scheduleTick, markConditionMet, getMode, isConditional), world/level/BaseCommandBlock.java
(performCommand, save, load, sendSystemMessage: ``[HH:mm:ss] `` + the message, acceptsSuccess,
acceptsFailure), commands/CommandSourceStack.java (sendSuccess, sendFailure), commands/FunctionCommand.java,
server/commands/SetBlockCommand.java and FillCommand.java (Level.blockUpdated after placing).
"""
from __future__ import annotations

import datetime
import functools
import json

from emulator.world.context import Context
from emulator.world.nbt_ops import is_numeric, numeric_value
from mcfunction_parser import ast, gamedata
from mcfunction_parser.commands import usage
from mcfunction_parser.nbt import Byte, Compound, Int, List, Long, String
from mcfunction_parser.parse import parse_function

IMPULSE, REPEATING, CHAIN = ("minecraft:command_block", "minecraft:repeating_command_block",
                             "minecraft:chain_command_block")
COMMAND_BLOCKS = frozenset((IMPULSE, REPEATING, CHAIN))
COMPONENT_TEXT_VERSION = (1, 21, 5)  # LastOutput saved as a text component's tag, a JSON string before
_OFFSETS = {"up": (0, 1, 0), "down": (0, -1, 0), "north": (0, 0, -1), "south": (0, 0, 1), "west": (-1, 0, 0),
            "east": (1, 0, 0)}
_OPPOSITE = {"up": "down", "down": "up", "north": "south", "south": "north", "west": "east", "east": "west"}
_Y_ROT = {"south": 0.0, "west": 90.0, "north": 180.0, "east": 270.0, "up": 270.0, "down": 270.0}  # Direction.toYRot
# neighbours whose signal the emulator does not work out (wires, repeaters, powered blocks ...)
_UNKNOWN_POWER = ("redstone_wire", "repeater", "comparator", "observer", "daylight_detector", "target",
                  "pressure_plate", "tripwire_hook", "trapped_chest", "lectern", "sculk_sensor", "piston")


def default_entity(block_id: str) -> Compound | None:
    """BaseCommandBlock.save and CommandBlockEntity.saveAdditional of a new command block."""
    if block_id not in COMMAND_BLOCKS:
        return None
    return Compound(Command=String(""), SuccessCount=Int(0), TrackOutput=Byte(1), UpdateLastExecution=Byte(1),
                    powered=Byte(0), conditionMet=Byte(0), auto=Byte(0))


def _flag(nbt: Compound, key: str, default: bool = False) -> bool:
    value = nbt.get(key)
    return bool(numeric_value(value)) if is_numeric(value) else default


def _facing(block) -> str:
    return dict(block.properties).get("facing", "north")


def _beside(pos, direction: str):
    dx, dy, dz = _OFFSETS[direction]
    return (pos[0] + dx, pos[1] + dy, pos[2] + dz)


# ---------------------------------------------------------------------- changes
def after_change(state, dimension: str, positions) -> None:
    """SetBlockCommand / FillCommand: each changed block loads, then its neighbours hear of it (in
    the level ``dimension``: its blocks and block ticks)."""
    state = state.level(dimension)
    blocks = state.blocks
    positions = [tuple(p) for p in positions]
    for pos in positions:
        if blocks.get(pos).id in COMMAND_BLOCKS:
            _set_automatic(state, pos, before=False)
    for pos in neighbours_of(blocks, positions, COMMAND_BLOCKS):
        _neighbour_changed(state, pos)


def neighbours_of(blocks, positions, block_ids) -> list:
    """The blocks among ``block_ids`` beside any of ``positions`` (Level.updateNeighborsAt), in order."""
    return sorted({n for pos in positions for n in (_beside(tuple(pos), d) for d in _OFFSETS)
                   if blocks.get(n).id in block_ids})


def after_edit(state, dimension: str, pos, before: Compound | None) -> None:
    """``data`` changed the command block's entity: CommandBlockEntity.loadAdditional."""
    state = state.level(dimension)
    if state.blocks.get(pos).id not in COMMAND_BLOCKS:
        return
    _set_automatic(state, tuple(pos), before=_flag(before or Compound(), "auto"))


def _set_automatic(state, pos, before: bool) -> None:
    """CommandBlockEntity.setAutomatic: ``auto`` rising schedules the tick (not powered, not a chain)."""
    nbt = state.blocks.entity(pos)
    if nbt is None:
        return
    if _flag(nbt, "auto") and not before and not _flag(nbt, "powered") and state.blocks.get(pos).id != CHAIN:
        _schedule(state, pos)


def _neighbour_changed(state, pos) -> None:
    """CommandBlock.setPoweredAndUpdate with Level.hasNeighborSignal."""
    nbt = state.blocks.entity(pos)
    powered = has_neighbour_signal(state, pos)
    if nbt is None or powered == _flag(nbt, "powered"):
        return
    nbt["powered"] = Byte(int(powered))
    if powered and not _flag(nbt, "auto") and state.blocks.get(pos).id != CHAIN:
        _schedule(state, pos)


def has_neighbour_signal(state, pos) -> bool:
    """Level.hasNeighborSignal for the sources modelled here."""
    found = False
    for direction in _OFFSETS:
        block = state.blocks.get(_beside(pos, direction))
        name, properties = block.id.removeprefix("minecraft:"), dict(block.properties)
        if name == "redstone_block" or (name in ("lever",) or name.endswith("_button")) and \
                properties.get("powered") == "true":
            found = True
        elif name in ("redstone_torch", "redstone_wall_torch") and properties.get("lit", "true") == "true":
            found = found or not _torch_on(block, direction)
        elif any(kind in name for kind in _UNKNOWN_POWER):
            state.error(f"the redstone signal of {block.id} (beside a block that reads its neighbours' signal)", severity="warning",
                        unmodelled=True)
    return found


def _torch_on(torch, direction: str) -> bool:
    """Whether the command block is the block the torch stands on or hangs from (no signal into it)."""
    if torch.id.endswith("redstone_torch"):
        return direction == "up"
    return _OPPOSITE[direction] == dict(torch.properties).get("facing", "north")


def _schedule(state, pos) -> None:
    """CommandBlockEntity.scheduleTick: markConditionMet, then the block's tick in 1 game tick."""
    _mark_condition_met(state, pos)
    state.block_ticks.schedule(pos, state.blocks.get(pos).id, 1, state.gametime, tick)


def _mark_condition_met(state, pos) -> bool:
    """CommandBlockEntity.markConditionMet: unconditional, or the block behind has SuccessCount > 0."""
    block, nbt = state.blocks.get(pos), state.blocks.entity(pos)
    met = True
    if dict(block.properties).get("conditional") == "true":
        behind = _beside(pos, _OPPOSITE[_facing(block)])
        there = state.blocks.entity(behind)
        met = state.blocks.get(behind).id in COMMAND_BLOCKS and there is not None and \
            is_numeric(there.get("SuccessCount")) and int(numeric_value(there["SuccessCount"])) > 0
    nbt["conditionMet"] = Byte(int(met))
    return met


# ---------------------------------------------------------------------- ticks
def tick(state, pos) -> None:
    """CommandBlock.tick."""
    block, nbt = state.blocks.get(pos), state.blocks.entity(pos)
    if nbt is None:
        return
    was_met = _flag(nbt, "conditionMet")
    conditional = dict(block.properties).get("conditional") == "true"
    if block.id == REPEATING:
        _mark_condition_met(state, pos)
    if block.id in (REPEATING, IMPULSE):
        if was_met:
            _execute(state, pos, block, nbt)
        elif conditional:
            nbt["SuccessCount"] = Int(0)
    if block.id == REPEATING and (_flag(nbt, "powered") or _flag(nbt, "auto")):
        state.block_ticks.schedule(pos, block.id, 1, state.gametime, tick)


def _execute(state, pos, block, nbt: Compound) -> None:
    """CommandBlock.execute: the command (an empty one only clears SuccessCount), then the chain."""
    if str(nbt.get("Command", "")):
        perform(state, pos, nbt)
    else:
        nbt["SuccessCount"] = Int(0)
    _execute_chain(state, pos, _facing(block))


def _execute_chain(state, pos, direction: str) -> None:
    """CommandBlock.executeChain."""
    steps = state.gamerules.max_command_chain_length
    while steps > 0:
        steps -= 1
        pos = _beside(pos, direction)
        block, nbt = state.blocks.get(pos), state.blocks.entity(pos)
        if block.id != CHAIN or nbt is None:
            break
        if _flag(nbt, "powered") or _flag(nbt, "auto"):
            if _mark_condition_met(state, pos):
                if not perform(state, pos, nbt):
                    break
            elif dict(block.properties).get("conditional") == "true":
                nbt["SuccessCount"] = Int(0)
        direction = _facing(block)


def perform(state, pos, nbt: Compound) -> bool:
    """BaseCommandBlock.performCommand: False when it already ran this game time."""
    track_time = _flag(nbt, "UpdateLastExecution", True)
    last = nbt.get("LastExecution")
    if track_time and is_numeric(last) and int(numeric_value(last)) == state.gametime:
        return False
    command = str(nbt.get("Command", ""))
    if command.lower() == "searge":  # the game's easter egg: no command runs, nor the time is kept
        nbt["LastOutput"] = _saved_component(state, "#itzlipofutzli")
        nbt["SuccessCount"] = Int(1)
        return True
    nbt["SuccessCount"] = Int(0)
    if command:  # the server's enable-command-block is taken as on, as a test server has it
        nbt.pop("LastOutput", None)
        block = state.blocks.get(pos)
        source = Context(pos=(pos[0] + 0.5, pos[1] + 0.5, pos[2] + 0.5), rot=(_Y_ROT[_facing(block)], 0.0),
                         dimension=getattr(state, "dimension", "minecraft:overworld"))
        successes = state.command_runner(command.removeprefix("/"), source) or 0
        nbt["SuccessCount"] = Int(successes)
        _last_output(state, nbt, command, successes > 0)
    if track_time:
        nbt["LastExecution"] = Long(state.gametime)
    else:
        nbt.pop("LastExecution", None)
    return True


# ---------------------------------------------------------------------- output
def _last_output(state, nbt: Compound, command: str, succeeded: bool) -> None:
    """BaseCommandBlock.sendSystemMessage: each message the command sends its source replaces
    ``LastOutput`` with ``[HH:mm:ss] `` (the wall clock) and the message, while ``TrackOutput``
    is on; a success's only when ``sendCommandFeedback`` is (acceptsSuccess), a failure's always
    (acceptsFailure). A command that sends none leaves no ``LastOutput``."""
    if not _flag(nbt, "TrackOutput", True):
        return
    messages = feedback(state, command, succeeded)
    stamp = "[" + datetime.datetime.now().strftime("%H:%M:%S") + "] "
    if messages is None:
        nbt["LastOutput"] = _saved_component(state, {"text": stamp})
        message = f"the output of the command block command `{command}` (LastOutput holds only its time here)"
        if not any(d.message == message for d in state.diagnostics):  # once, not every tick of a repeating block
            state.error(message, severity="warning", unmodelled=True)
        return
    feedback_on = state.gamerules.get("sendCommandFeedback") != "false"
    shown = [text for text, failure in messages if failure or feedback_on]
    if shown:
        nbt["LastOutput"] = _saved_component(state, {"text": stamp, "extra": [shown[-1]]})


def feedback(state, command: str, succeeded: bool) -> list[tuple[object, bool]] | None:
    """The messages ``command`` sends its source (each a text component and whether it is a
    failure), for the commands whose messages the emulator knows; None for the others. Functions
    the command calls send none (FunctionCommand runs them withSuppressedOutput)."""
    final = _final_command(command, tuple(state.version))
    if isinstance(final, (ast.Tellraw, ast.Say)) and succeeded:
        return []  # TellRawCommand sends nothing back; say broadcasts to the players only
    if isinstance(final, ast.Return) and final.kind != "run":
        return []
    if isinstance(final, ast.GenericCommand) and final.name == "help":
        return _help_feedback(state, final.text.partition(" ")[2] or None)
    if isinstance(final, ast.FunctionCall) and final is _command(command, tuple(state.version)):
        return _function_feedback(state, final)
    return None


def _function_feedback(state, call: ast.FunctionCall) -> list[tuple[object, bool]] | None:
    """FunctionCommand.FunctionCustomExecutor.runGuarded sends ``Running function ID`` (one
    function) or ``Running functions A, B`` (ComponentUtils.formatList, a grey ", ") before they
    run. A function that returns a value then sends ``Function ID returned N``
    (decorateOutputIfNeeded; the command block's source is not silent): not produced here, so a
    function with a ``return``, a macro line or arguments (which may fail to instantiate) is
    not modelled (None), nor a name that finds no function (the command fails)."""
    functions = state.functions_named(call.function, call.is_tag) if state.functions_named else []
    if (not functions or call.arguments is not None or call.with_source is not None
            or any(f.is_macro or any(_returns(c) for c in f.commands) for f in functions)):
        return None
    if len(functions) == 1:
        return [({"translate": "commands.function.scheduled.single", "with": [functions[0].id]}, False)]
    listed: list = []
    for function in functions:
        listed += [{"text": ", ", "color": "gray"}, function.id] if listed else [function.id]
    return [({"translate": "commands.function.scheduled.multiple", "with": [{"text": "", "extra": listed}]}, False)]


def _returns(node) -> bool:
    """Whether the command is or ends in ``return`` (its function's frame then has a result)."""
    while isinstance(node, ast.Execute) and node.run is not None:
        node = node.run
    return isinstance(node, ast.Return)


def _help_feedback(state, text: str | None) -> list[tuple[object, bool]] | None:
    try:
        lines = usage.help_messages(gamedata.command_tree(tuple(state.version)), text)
    except (gamedata.GameDataMissing, usage.OrderUnknown, ValueError):
        return None
    if lines is None:  # CommandSourceStack.sendFailure: the message in red
        return [({"text": "", "extra": [{"translate": "commands.help.failed"}], "color": "red"}, True)]
    return [(line, False) for line in lines]


@functools.lru_cache(maxsize=256)
def _command(command: str, version: tuple[int, int, int]):
    """The command block's command parsed; None if it does not parse."""
    function, errors = parse_function(command.removeprefix("/"), "<command block>", "dpemu:command_block", version)
    return function.commands[0] if function.commands and not errors else None


def _final_command(command: str, version: tuple[int, int, int]):
    """The command an ``execute ... run`` chain (or ``return run``) ends with; None if it does not parse."""
    node = _command(command, version)
    while True:
        if isinstance(node, ast.Execute) and node.run is not None:
            node = node.run
        elif isinstance(node, ast.Return) and node.kind == "run":
            node = node.command
        else:
            return node


def _saved_component(state, component):
    """A text component as the block entity saves it: its tag from 1.21.5, a JSON string before."""
    if tuple(state.version) >= COMPONENT_TEXT_VERSION:
        return _as_tag(component)
    return String(json.dumps(component, separators=(",", ":"), ensure_ascii=False))


def _as_tag(value):
    if isinstance(value, dict):
        return Compound({k: _as_tag(v) for k, v in value.items()})
    if isinstance(value, list):
        return List(_as_tag(v) for v in value)
    return String(value)
