"""A player that has just joined or respawned takes no damage for a while.

- Up to 1.21.3, ServerPlayer.spawnInvulnerableTime: 60 ticks from the player's creation (joining,
  respawning: a new player), counted down first thing in ServerPlayer.tick, in which
  ServerPlayer.hurt refuses any damage that does not bypass invulnerability (``kill``'s and the
  void's do): every player, a client's or a PackTest dummy. (On a dedicated server with PvP on,
  fall damage gets through: the emulator runs as PackTest's GameTestServer, which is not one.)
- From 1.21.4, ServerPlayer.isInvulnerableTo holds while ``!hasClientLoaded()``, for any damage.
  A client tells the server it has loaded the level (ServerboundPlayerLoadedPacket:
  setClientLoaded(true)) within its first ticks: the emulator takes a player a client drives as
  loaded at once. A PackTest dummy has no client: it waits for the timeout, 60 of its ticks
  (Player.clientLoadedTimeoutTimer, counted down first thing in ServerPlayer.tick; 26.1 keeps it in
  the connection: ServerGamePacketListenerImpl.tickClientLoadTimeout), from its spawn and from each
  respawn.

- ``joined(state, player, client)``: a player joined or respawned (``client``: a client drives it).
- ``tick(state)``: the timers count down; ``tick_is_idle(state)``: none is protected.
- ``refuses(state, player, bypasses) -> bool``: whether a damage is refused (``bypasses``: its type
  is in #bypasses_invulnerability).

Sources (decompiled): 1.16.5, 1.20.6, 1.21.3 server/level/ServerPlayer.java (spawnInvulnerableTime,
tick, hurt); 1.21.4 and 1.21.7 world/entity/player/Player.java (hasClientLoaded,
tickClientLoadTimeout, setClientLoaded), ServerPlayer.java (tick, isInvulnerableTo, die); 26.1.2
server/network/ServerGamePacketListenerImpl.java (hasClientLoaded).
"""
from __future__ import annotations

CLIENT_LOAD_VERSION = (1, 21, 4)
TICKS = 60


def joined(state, player, client: bool) -> None:
    if state.version < CLIENT_LOAD_VERSION or not client:
        state.protected[player] = TICKS


def tick_is_idle(state) -> bool:
    return not state.protected


def tick(state) -> None:
    if not state.protected:
        return
    for player, left in list(state.protected.items()):
        if left <= 1 or not player.alive:
            del state.protected[player]
        else:
            state.protected[player] = left - 1


def refuses(state, player, bypasses: bool) -> bool:
    if not state.protected or player not in state.protected:
        return False
    return state.version >= CLIENT_LOAD_VERSION or not bypasses
