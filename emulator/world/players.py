"""Players joining and leaving the server, at any tick, as the game's PlayerList handles them.

- ``join(state, name, pos, ...)``: PlayerList.placeNewPlayer: a player of that name already online
  is disconnected first (``disconnectAllPlayersWithProfile``, so it leaves as below); the new one
  has the offline-mode UUID of its name (``UUIDUtil.createOfflinePlayerUUID``: the same UUID each
  time it joins), and goes to the end of the player list and of the entity order (``@a`` and
  ``@e`` visit players in join order). Its scores are kept by name, so a rejoining player finds
  them. ``on_ground`` sets ``OnGround``: a client's player moves only by its client (ServerPlayer.
  tick does not call travel), so the server never lands it; PackTest's dummies fall
  (emulator.world.falling).
- ``leave(state, player)``: PlayerList.remove: ``minecraft.custom:minecraft.leave_game`` + 1, then
  the player is gone from the world (its scores stay).
- ``place(player, pos=None, rotation=None, on_ground=None)``: move a player or set its
  ``OnGround`` (what a client would report; the API's and ``--player``'s way to stand a player).
- ``offline_uuid(name)``.

Sources (decompiled 1.21): server/players/PlayerList.java (placeNewPlayer, remove,
disconnectAllPlayersWithProfile), core/UUIDUtil.java (createOfflinePlayerUUID), world/entity/player/
Player.java (awardStat).
"""
from __future__ import annotations

import hashlib
import uuid as uuid_lib

import numpy as np

from emulator.world import living, spawn_protection, statistics
from mcfunction_parser.nbt import Byte, Int


def offline_uuid(name: str) -> tuple[int, int, int, int]:
    """``UUIDUtil.createOfflinePlayerUUID``: ``UUID.nameUUIDFromBytes("OfflinePlayer:" + name)``."""
    value = uuid_lib.UUID(bytes=hashlib.md5(f"OfflinePlayer:{name}".encode()).digest(), version=3).int
    return tuple(((value >> shift) + 2**31) % 2**32 - 2**31 for shift in (96, 64, 32, 0))  # int[4]


def online(state, name: str):
    return next((p for p in state.entities.players() if p.player_name == name), None)


def join(state, name: str, pos, rotation=(0.0, 0.0), gamemode: str | None = None, level: int = 0,
         on_ground: bool = True, dimension: str = "minecraft:overworld"):
    """A player named ``name`` joins (the one already online of that name leaves first), in
    ``gamemode`` or else the world's default game mode (``defaultgamemode``)."""
    if gamemode is None:
        gamemode = state.level_settings.default_gamemode
    previous = online(state, name)
    if previous is not None:
        leave(state, previous)
    player = state.entities.add_player(name, tuple(float(c) for c in pos), rotation[0], rotation[1], gamemode, level,
                                       dimension)
    player.uuid = offline_uuid(name)
    player.data["OnGround"] = Byte(1 if on_ground else 0)
    player.data["XpLevel"] = Int(level)
    living.reset_attack_strength(state, player)
    spawn_protection.joined(state, player, client=True)
    return player


def leave(state, player) -> None:
    statistics.award(state, player, statistics.stat_name("custom", "leave_game"))
    state.entities.kill(player)


def place(player, pos=None, rotation=None, on_ground: bool | None = None) -> None:
    if pos is not None:
        player.pos = tuple(float(c) for c in pos)
    if rotation is not None:
        player.yaw, player.pitch = np.float32(rotation[0]), np.float32(rotation[1])
    if on_ground is not None:
        player.data["OnGround"] = Byte(1 if on_ground else 0)
