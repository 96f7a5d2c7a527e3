"""The commands that show or play something to players: ``title``, ``particle``, ``playsound``,
``stopsound``, ``msg``/``tell``/``w``, ``me``, ``teammsg``, ``dialog``, ``swing`` and ``version``.
What a pack can read back of them is their result (and, for the chat commands, the line in the
log); what the players see or hear is not modelled and needs not be.

Sources (decompiled 26.1.2 and 1.21.3): TitleCommand (each form returns the number of targets),
ParticleCommand.sendParticles with ServerLevel.sendParticles (a player in the source's level whose
block's centre is closer than 32 blocks, 512 with ``force``: the result counts them, none fails),
PlaySoundCommand.playSound (a player within the sound's range, 16 or 16 x volume, or any with a
minimum volume; none fails), StopSoundCommand, MsgCommand.sendMessage (the targets; each reads
"NAME whispers to you: MESSAGE"), EmoteCommands (result 1), TeamMsgCommand (the team's players and the
sender), DialogCommand, SwingCommand (the living targets; none fails).
"""
from __future__ import annotations

import json
import math

import numpy as np

from emulator.world import living, text_components
from emulator.world.text import plain_text
from emulator.world.errors import CommandFailure, Unmodelled
from mcfunction_parser import ast, selectors
from mcfunction_parser.arguments import holder_from_word, vec3
from mcfunction_parser.particles import particle as read_particle
from mcfunction_parser.reader import Reader

from . import entities
from .level import Words
from .server import sender_name

PARTICLE_RANGE, FORCED_PARTICLE_RANGE = 32.0, 512.0
SOUND_RANGE = np.float32(16.0)  # SoundEvent.createVariableRangeEvent: getRange
# PlaySoundCommand skips a player in another level from a release between 1.21.4 (no check, as in
# 1.21.3) and 1.21.7 (the check): which one is not known here
SOUND_SAME_LEVEL_KNOWN, SOUND_SAME_LEVEL = (1, 21, 4), (1, 21, 7)


def _target(words: Words):
    """An entity argument: a selector, a player name or a UUID."""
    reader = words.reader
    if reader.peek() == "@":
        return words.read(selectors.selector)
    return holder_from_word(words.read(Reader.word), reader.loc())


def _players(env, words: Words, ctx) -> list:
    return entities.players_found(env.state, _target(words), ctx)


def title(env, cmd: ast.GenericCommand, ctx) -> int:
    words = Words(env, cmd)
    return len(_players(env, words, ctx))


def stopsound(env, cmd: ast.GenericCommand, ctx) -> int:
    return len(_players(env, Words(env, cmd), ctx))


def dialog(env, cmd: ast.GenericCommand, ctx) -> int:
    words = Words(env, cmd)
    words.word()  # show | clear
    return len(_players(env, words, ctx))


def particle(env, cmd: ast.GenericCommand, ctx) -> int:
    """``particle NAME [POS [DELTA SPEED COUNT [force|normal [VIEWERS]]]]``: the viewers (every
    player by default) who get it."""
    state = env.state
    words = Words(env, cmd)
    words.read(read_particle)
    source = entities.world_source(state, ctx)
    pos = source.position_of(words.read(vec3)) if words.more() else source.pos
    force, viewers = False, None
    if words.more():
        words.read(vec3)  # delta
        words.read(Reader.word)  # speed
        words.read(Reader.word)  # count
        if words.more():
            force = words.read(Reader.word) == "force"
            if words.more():
                viewers = _players(env, words, ctx)
    if viewers is None:
        viewers = state.entities.players()
    reach = (FORCED_PARTICLE_RANGE if force else PARTICLE_RANGE) ** 2
    shown = sum(player.dimension == ctx.dimension and _block_centre_distance_sqr(player.pos, pos) < reach
                for player in viewers)
    if not shown:
        raise CommandFailure("commands.particle.failed")
    return shown


def _block_centre_distance_sqr(player_pos, pos) -> float:
    """Vec3i.distToCenterSqr of the player's block position."""
    return sum((math.floor(p) + 0.5 - q) ** 2 for p, q in zip(player_pos, pos))


def playsound(env, cmd: ast.GenericCommand, ctx) -> int:
    """``playsound SOUND [SOURCE [TARGETS [POS [VOLUME [PITCH [MIN_VOLUME]]]]]]``: the targets (the
    executing player by default) who hear it."""
    state = env.state
    words = Words(env, cmd)
    words.read(Reader.word)  # the sound
    if words.more():
        words.read(Reader.word)  # its source
    source = entities.world_source(state, ctx)
    if words.more():
        players = _players(env, words, ctx)
    else:  # getCallingPlayerAsCollection
        executor = entities.executor(state, ctx)
        players = [executor] if executor is not None and executor.is_player else []
    pos = source.position_of(words.read(vec3)) if words.more() else source.pos
    volume = np.float32(words.read(Reader.double)) if words.more() else np.float32(1.0)
    if words.more():
        words.read(Reader.double)  # pitch
    min_volume = words.read(Reader.double) if words.more() else 0.0
    reach = np.float32(SOUND_RANGE * volume if volume > 1.0 else SOUND_RANGE)
    reach_sqr = float(np.float32(reach * reach))  # Mth.square(float)
    heard = 0
    for player in players:
        if player.dimension != ctx.dimension and tuple(state.version) > SOUND_SAME_LEVEL_KNOWN:
            if tuple(state.version) < SOUND_SAME_LEVEL:
                raise Unmodelled("playsound for a player in another level (from which release it is skipped)")
            continue
        if sum((q - p) ** 2 for p, q in zip(player.pos, pos)) > reach_sqr and min_volume <= 0.0:
            continue
        heard += 1
    if not heard:
        raise CommandFailure("commands.playsound.failed")
    return heard


def msg(env, cmd: ast.GenericCommand, ctx) -> int:
    """``msg|tell|w TARGETS MESSAGE``: each target reads "NAME whispers to you: MESSAGE" (the
    msg_command_incoming chat type), a chat message PackTest's recorder does not hear."""
    state = env.state
    words = Words(env, cmd)
    players = _players(env, words, ctx)
    text = text_components.say_text(words.reader.rest(), lambda sel: entities.select(state, sel, ctx))
    state.emit("msg", f"{sender_name(env, ctx)} whispers to you: {text}", cmd.loc,
               tuple(p.uuid_string for p in players))
    return len(players)


def me(env, cmd: ast.GenericCommand, ctx) -> int:
    """``me ACTION`` (EmoteCommands): every player reads "* NAME ACTION"; the result is 1."""
    state = env.state
    words = Words(env, cmd)
    text = text_components.say_text(words.reader.rest(), lambda sel: entities.select(state, sel, ctx))
    state.broadcast("me", f"* {sender_name(env, ctx)} {text}", cmd.loc)
    return 1


def teammsg(env, cmd: ast.GenericCommand, ctx) -> int:
    """``teammsg|tm MESSAGE`` (TeamMsgCommand): the executor's team mates online read
    "[TEAM] <NAME> MESSAGE", a player sending it "-> [TEAM] <NAME> MESSAGE"; the result counts them."""
    state = env.state
    sender = entities._executor_required(state, ctx)
    if sender.team is None:
        raise CommandFailure("commands.teammsg.failed.noteam")
    words = Words(env, cmd)
    text = text_components.say_text(words.reader.rest(), lambda sel: entities.select(state, sel, ctx))
    team = state.teams.team(sender.team)
    line = f"[{plain_text(json.dumps(team.display_name), state.version)}] <{sender_name(env, ctx)}> {text}"
    receivers = [p for p in state.entities.players() if p is sender or p.team == sender.team]
    mates = tuple(p.uuid_string for p in receivers if p is not sender)
    if mates:
        state.emit("teammsg", line, cmd.loc, mates)
    if sender in receivers:
        state.emit("teammsg", f"-> {line}", cmd.loc, (sender.uuid_string,))
    return len(receivers)


def swing(env, cmd: ast.GenericCommand, ctx) -> int:
    """``swing [TARGETS [mainhand|offhand]]`` (26.1+): the living targets swing an arm; the executor
    by default."""
    state = env.state
    words = Words(env, cmd)
    targets = (entities.found(state, _target(words), ctx) if words.more()
               else [entities._executor_required(state, ctx)])
    swung = sum(living.is_living(entity.type) for entity in targets)
    if not swung:
        raise CommandFailure("commands.swing.failed.notliving")
    return swung


def version(env, cmd: ast.GenericCommand, ctx) -> int:
    """``version`` (1.21.6+, VersionCommand): the game's version told to the source; 1."""
    return 1


GENERIC_HANDLERS = {"title": title, "particle": particle, "playsound": playsound, "stopsound": stopsound,
                    "msg": msg, "tell": msg, "w": msg, "dialog": dialog, "swing": swing,
                    "me": me, "teammsg": teammsg, "tm": teammsg, "version": version}
