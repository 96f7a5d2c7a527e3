"""A spectator's camera: ``spectate`` puts a player in spectator mode behind another entity's eyes,
and each tick the player follows it (cutscene packs read where the player is).

Sources (decompiled 26.1.2): SpectateCommand.spectate, ServerPlayer.setCamera (a new camera moves
the player to it, in its level, the player's own rotation kept), ServerPlayer.tick (while the camera
lives the player snaps to its position and rotation, Entity.absSnapTo; sneaking or a dead camera
ends it), ServerPlayer.setGameMode (any mode but spectator ends it) and ServerPlayer.teleportTo
(``tp`` and ``spreadplayers`` end it: resetCamera). The camera is not saved in the player's NBT.

A teleport is seen as the game would see it: a player no longer where its camera left it at the
last snap was moved by a command, which ended the camera then.
"""
from __future__ import annotations

import numpy as np

from emulator.world.errors import CommandFailure
from emulator.world.teleport import Destination, apply

SPECTATE_CHECKS_TYPE = (1, 21, 9)  # "cannot be spectated": a type the client does not track (markers)
UNTRACKED_TYPES = frozenset({"minecraft:marker"})  # EntityType clientTrackingRange(0)


def spectate(state, target, player) -> int:
    """SpectateCommand.spectate: ``target`` None stops; the result is 1."""
    if target is player:
        raise CommandFailure("commands.spectate.self")
    if player.gamemode != "spectator":
        raise CommandFailure("commands.spectate.not_spectator", player.display_name)
    if target is not None and target.type in UNTRACKED_TYPES and tuple(state.version) >= SPECTATE_CHECKS_TYPE:
        raise CommandFailure("commands.spectate.cannot_spectate", target.display_name)
    set_camera(state, player, target)
    return 1


def set_camera(state, player, camera) -> None:
    """ServerPlayer.setCamera: a new camera takes the player to it (Entity.teleportTo with the
    player's rotation); None (or the player) is the player's own eyes again."""
    cameras = state.cameras
    old = cameras.get(player, (None, None))[0]
    new = None if camera is player else camera
    if old is new:
        return
    if new is None:
        cameras.pop(player, None)
        return
    apply(player, Destination(new.pos, player.yaw, player.pitch, new.dimension), state.entities, state.version)
    cameras[player] = (new, player.pos)


def stop(state, player) -> None:
    """setCamera(this): a game mode change or a teleport ends spectating."""
    state.cameras.pop(player, None)


def tick_cameras(state) -> None:
    """ServerPlayer.tick's camera step, for each player behind a camera."""
    if not state.cameras:  # every tick: nobody spectating is the common case
        return
    for player, (camera, snapped) in list(state.cameras.items()):
        if player.pos != snapped or player.gamemode != "spectator" or not player.alive:
            stop(state, player)  # teleported or no longer a spectator: the camera ended then
        elif not camera.alive or player.sneaking:  # a dead camera; wantsToStopRiding: sneaking
            stop(state, player)
        else:
            player.pos = camera.pos
            player.yaw = np.float32(np.fmod(np.float32(camera.yaw), np.float32(360.0)))
            pitch = min(max(np.float32(camera.pitch), np.float32(-90.0)), np.float32(90.0))
            player.pitch = np.float32(np.fmod(pitch, np.float32(360.0)))
            state.cameras[player] = (camera, player.pos)


def tick_is_idle(state) -> bool:
    return not state.cameras
