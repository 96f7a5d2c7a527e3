"""PackTest's ``dummy`` command: simulated players (``Dummy``, a ServerPlayer) that a test spawns and
makes act, with what a datapack can observe of each action (misode/packtest DummyCommand.java,
Dummy.java, PackTestExecutor.java; the game's Player and Interaction classes).

    dummy <player> spawn | leave | respawn | jump | sneak <bool> | sprint <bool> | selectslot <1..9>
                   | attack <entity> | use entity <entity> [<pos>] | mine <pos>
                   | drop [all] | swap | use item | use block <pos> [<direction>]

Modelled:
- ``spawn``: a survival player named as written (a plain name; ``@s`` has none) joins at the test
  source's position (emulator.world.players.join: the offline-mode UUID the game gives it),
  not on the ground (the ``@dummy`` one stands: PackTestFunction's ``setOnGround(true)``). From the
  next tick the server ticks its physics (Dummy.tick -> doTick): it falls, lands (``OnGround``),
  takes fall damage (emulator.world.falling).
- ``leave``: emulator.world.players.leave: ``minecraft.custom:minecraft.leave_game`` + 1, then the
  player is gone (scores stay).
- ``respawn``: a new player entity with the same name and UUID at the dummy's first spawn
  position, rotation 0 0 (PackTest's PlayerListMixin), sneak/sprint released, slot 1, keeping what
  ServerPlayer.restoreFrom keeps (emulator.world.combat: tags, ender chest, with keepInventory the
  inventory and experience).
- ``jump``: only from the ground; LivingEntity.jumpFromGround (emulator.world.falling.jump): the
  jump's motion, ``minecraft.custom:minecraft.jump`` + 1, the food exhaustion; the dummy rises and
  lands again over the next ticks.
- ``sneak``/``sprint``: the key state (failing when unchanged, as PackTest does); a sneaking player
  earns ``minecraft.custom:minecraft.sneak_time`` every tick (emulator.world.statistics). Sprinting is
  observable only through predicates, which the emulator does not evaluate.
- ``selectslot N``: ``SelectedItemSlot`` (N - 1) in the player's NBT.
- ``attack`` on an ``interaction`` entity: its ``attack`` NBT ``{player: UUID, timestamp: game
  time}`` and ``player_hurt_entity`` (Interaction.skipAttackInteraction); ``use entity``:
  emulator.world.entity_use (Entity.interactAt at the position given, else the entity's own, then
  Player.interactOn, as PackTest's useEntity calls them).
- ``attack`` on a living entity: Player.attack (emulator.world.combat.attack):
  the damage grows with the ticks since the dummy joined or last attacked (x 1.5 for a
  critical hit while falling), the target's
  ``Health`` and ``HurtTime``, ``damage_dealt``, a death (emulator.world.combat). A target that
  is not living is not attackable: nothing happens, as in the game. Knockback is not modelled.
- The block actions act in the dummy's level (its blocks and block ticks: WorldState.level).
- ``mine``: emulator.world.block_breaking (ServerPlayerGameMode.destroyBlock; the held tool: emulator.world.tools).
- ``drop [all]``, ``swap``, ``use item``: emulator.world.player_actions (the item entity with its
  ``Thrower``, the hands' stacks, the items whose use is modelled, using an item over ticks);
  ``use block``: emulator.world.block_use (each hand in turn until one consumes the action).

Not modelled, so a test using them is inconclusive with the reason: what the world modules say
they do not model (an item's use, a block's or a mob's interaction, mining with a tool ...).

As in PackTest, an action the game refuses (``Dummy X is not on the ground`` ...) is a failed
command: the test goes on, and the message is kept as a runtime diagnostic.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

from emulator.commands import entities as world_entities
from emulator.world.context import Context
from emulator.world import (block_breaking, block_use, combat, entity_use, falling, player_actions, players,
                           spawn_protection)
from emulator.world.blocks import block_pos
from emulator.world.entities import Entity
from emulator.world.errors import CommandFailure, Unmodelled
from mcfunction_parser import ast, selectors
from mcfunction_parser.arguments import holder_from_word, vec3
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.nbt import Int
from mcfunction_parser.reader import Reader

ACTIONS = ("spawn", "leave", "respawn", "jump", "swap", "sneak", "sprint", "drop", "selectslot", "use", "attack",
           "mine")
DIRECTIONS = ("down", "up", "north", "south", "west", "east")


@dataclass(frozen=True)
class DummyCommand:
    """One parsed ``dummy`` line."""

    target: object  # ast.Selector or ast.NameTarget
    action: str  # an entry of ACTIONS, "use item|block|entity" spelled out
    flag: bool | None = None  # sneak/sprint's active, drop's all
    slot: int | None = None
    entity: object = None  # attack / use entity
    pos: ast.Vec3 | None = None  # use block / use entity / mine
    face: str = "up"  # use block's direction as written (checked when it runs, as PackTest does)
    text: str = ""  # the line as written, for messages


class DummyFailure(Exception):
    """The game refuses the action: the command fails, the test goes on."""


class Unsupported(Exception):
    """The emulator cannot carry the action out faithfully: the test fails with the reason."""


# ---------------------------------------------------------------------- parsing
def parse(text: str, loc: Loc, version) -> DummyCommand:
    """``dummy ...`` (the whole command) as DummyCommand's brigadier tree reads it; raises
    mcfunction_parser's ParseError (with the offset in ``text``) when malformed."""
    r = Reader(text, loc, version)
    r.pos = len("dummy")
    r.space("a player")
    target = _entity(r)
    r.space("an action")
    action = _word(r)
    if action not in ACTIONS:
        r.fail(f"dummy: unknown action {action!r}: expected one of " + ", ".join(ACTIONS), r.pos - len(action))
    command = DummyCommand(target, action, text=text)
    if action in ("sneak", "sprint"):
        r.space("true or false")
        word = _word(r)
        if word not in ("true", "false"):
            r.fail(f"dummy {action}: expected true or false, got {word!r}", r.pos - len(word))
        command = replace(command, flag=word == "true")
    elif action == "drop" and r.optional_space():
        word = _word(r)
        if word != "all":
            r.fail(f"dummy drop: expected 'all' or nothing, got {word!r}", r.pos - len(word))
        command = replace(command, flag=True)
    elif action == "selectslot":
        r.space("a hotbar slot 1..9")
        word = _word(r)
        if not word.isdigit() or not 1 <= int(word) <= 9:
            r.fail(f"dummy selectslot: expected a hotbar slot 1..9, got {word!r}", r.pos - len(word))
        command = replace(command, slot=int(word))
    elif action == "attack":
        r.space("an entity")
        command = replace(command, entity=_entity(r))
    elif action == "mine":
        r.space("a block position")
        command = replace(command, pos=vec3(r, block=True))
    elif action == "use":
        command = _use(r, command)
    r.finish()
    return command


def _use(r: Reader, command: DummyCommand) -> DummyCommand:
    r.space("item, block or entity")
    what = _word(r)
    if what == "item":
        return replace(command, action="use item")
    if what == "block":
        r.space("a position")
        command = replace(command, action="use block", pos=vec3(r))
        return replace(command, face=_word(r)) if r.optional_space() else command
    if what == "entity":
        r.space("an entity")
        command = replace(command, action="use entity", entity=_entity(r))
        return replace(command, pos=vec3(r)) if r.optional_space() else command
    r.fail(f"dummy use: expected item, block or entity, got {what!r}", r.pos - len(what))


def _word(r: Reader) -> str:
    start = r.pos
    while r.more() and r.peek() != " ":
        r.pos += 1
    return r.text[start:r.pos]


def _entity(r: Reader):
    """EntityArgument.entity(): a selector, a player name or a UUID."""
    if r.peek() == "@":
        return selectors.selector(r)
    start = r.pos
    return holder_from_word(_word(r), r.loc_at(start))


# ---------------------------------------------------------------------- running
class Dummies:
    """The dummies of one test world: which players are dummies, and where each first spawned."""

    def __init__(self, state) -> None:
        self.state = state
        self.spawns: dict[tuple, tuple[float, float, float]] = {}  # UUID -> first spawn position

    def spawn(self, name: str, pos, on_ground: bool = False) -> Entity:
        """A new dummy ``name`` at ``pos`` (Dummy.create: a new player is not on the ground until its
        first landing; PackTestFunction stands the ``@dummy`` one with ``setOnGround(true)``)."""
        for player in self.state.entities.players():
            if player.player_name == name:
                kind = "is already logged on" if player.uuid in self.spawns else "is already a player"
                raise DummyFailure(f"Dummy {name} {kind}")
        player = players.join(self.state, name, pos, on_ground=on_ground)
        player.data["SelectedItemSlot"] = Int(0)
        falling.fall(self.state, player)  # Dummy.tick runs doTick: the server ticks its physics
        spawn_protection.joined(self.state, player, client=False)  # no client: 60 ticks until it counts as loaded
        self.spawns[player.uuid] = tuple(pos)
        return player

    def run(self, command: DummyCommand, ctx: Context) -> None:
        """Carry out ``command`` run from ``ctx``; DummyFailure / Unsupported as described above."""
        if command.action == "spawn":
            if not isinstance(command.target, ast.NameTarget) or command.target.is_uuid:
                raise DummyFailure("Cannot spawn dummy without a name")
            self.spawn(command.target.name, ctx.pos)
            return
        dummy = self._dummy(command.target, ctx)
        try:
            getattr(self, "_" + command.action.replace(" ", "_"))(dummy, command, ctx)
        except Unmodelled as error:
            raise Unsupported(error.message.removeprefix("not modelled: ")) from None

    def _select(self, target, ctx: Context) -> list[Entity]:
        try:
            return world_entities.select(self.state, target, ctx)
        except CommandFailure as error:  # a selector the world library cannot read
            raise (Unsupported if error.report else DummyFailure)(error.message) from None

    def _dummy(self, target, ctx: Context) -> Entity:
        """DummyCommand.getDummy: exactly one player, and a dummy."""
        found = self._select(target, ctx)
        if len(found) != 1 or not found[0].is_player or found[0].uuid not in self.spawns:
            raise DummyFailure("No dummy was found")
        return found[0]

    def _entity(self, target, ctx: Context) -> Entity:
        found = self._select(target, ctx)
        if not found:
            raise DummyFailure("No entity was found")
        if len(found) > 1:
            raise DummyFailure("Only one entity is allowed, but the provided selector allows more than one")
        return found[0]

    # ---------------------------------------------------------------- actions
    def _leave(self, dummy: Entity, command, ctx) -> None:
        block_use.close_menu(self.state, dummy)
        players.leave(self.state, dummy)

    def _respawn(self, dummy: Entity, command, ctx) -> None:
        """PlayerList.respawn: a new player at the dummy's first spawn (Dummy.adjustSpawnLocation),
        keeping what ServerPlayer.restoreFrom keeps."""
        spawn = self.spawns.pop(dummy.uuid)
        block_use.close_menu(self.state, dummy)
        self.state.entities.kill(dummy)
        reborn = self.spawn(dummy.player_name, spawn)
        combat.respawn_keeps(self.state, dummy, reborn)

    def _jump(self, dummy: Entity, command, ctx) -> None:
        if not dummy.data.get("OnGround"):
            raise DummyFailure(f"Dummy {dummy.player_name} is not on the ground")
        falling.jump(self.state, dummy)

    def _sneak(self, dummy: Entity, command, ctx) -> None:
        if dummy.sneaking == command.flag:
            raise DummyFailure(f"Dummy {dummy.player_name} is already {'' if command.flag else 'not '}sneaking")
        dummy.sneaking = command.flag

    def _sprint(self, dummy: Entity, command, ctx) -> None:
        if dummy.sprinting == command.flag:
            raise DummyFailure(f"Dummy {dummy.player_name} is already {'' if command.flag else 'not '}sprinting")
        dummy.sprinting = command.flag

    def _selectslot(self, dummy: Entity, command, ctx) -> None:
        if int(dummy.data.get("SelectedItemSlot", Int(0))) == command.slot - 1:
            raise DummyFailure(f"Dummy {dummy.player_name} already has slot {command.slot} selected")
        dummy.data["SelectedItemSlot"] = Int(command.slot - 1)

    def _attack(self, dummy: Entity, command, ctx) -> None:
        entity_use.attack(self.state, dummy, self._entity(command.entity, ctx))

    def _use_entity(self, dummy: Entity, command, ctx) -> None:
        """DummyCommand.useEntity: each hand in turn, Entity.interactAt at the position given (the
        entity's own when none is) then Player.interactOn, until one consumes the action."""
        target = self._entity(command.entity, ctx)
        at = target.pos if command.pos is None else world_entities.world_source(self.state, ctx).position_of(
            command.pos, centre=False)
        for hand in (player_actions.MAIN, player_actions.OFF):
            if entity_use.interact_at(self.state, dummy, hand, target, at) == "consume":
                return
            if entity_use.interact_on(self.state, dummy, hand, target) == "consume":
                return
        raise DummyFailure(f"Dummy {dummy.player_name} cannot interact with that entity")

    def _mine(self, dummy: Entity, command, ctx) -> None:
        pos = block_pos(world_entities.world_source(self.state, ctx), command.pos)
        if not block_breaking.destroy_block(self.state.level(dummy.dimension), dummy, pos):
            raise DummyFailure(f"Dummy {dummy.player_name} failed to mine block")

    def _drop(self, dummy: Entity, command, ctx) -> None:
        if player_actions.drop_selected(self.state, dummy, bool(command.flag)) is None:
            raise DummyFailure(f"Dummy {dummy.player_name} is not holding an item in their mainhand")

    def _swap(self, dummy: Entity, command, ctx) -> None:
        player_actions.swap_hands(self.state, dummy)

    def _use_item(self, dummy: Entity, command, ctx) -> None:
        """DummyCommand.useItem: the main hand, then the offhand, until one consumes the action."""
        for hand in (player_actions.MAIN, player_actions.OFF):
            if player_actions.use_item(self.state, dummy, hand) == "consume":
                return
        raise DummyFailure(f"Dummy {dummy.player_name} cannot use that item")

    def _use_block(self, dummy: Entity, command, ctx) -> None:
        """DummyCommand.useBlock: each hand in turn, until one consumes the action."""
        if command.face not in DIRECTIONS:
            raise DummyFailure("Not a valid direction")
        hit = world_entities.world_source(self.state, ctx).position_of(command.pos, centre=False)
        pos = tuple(math.floor(v) for v in hit)  # BlockPos.containing
        level = self.state.level(dummy.dimension)  # the dummy's level (DummyCommand: dummy.serverLevel())
        for hand in (player_actions.MAIN, player_actions.OFF):
            if block_use.use_item_on(level, dummy, hand, pos, command.face, hit) == "consume":
                return
        raise DummyFailure(f"Dummy {dummy.player_name} cannot interact with that block")
