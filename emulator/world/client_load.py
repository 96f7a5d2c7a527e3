"""Players whose client has not loaded yet take no damage: from 1.21.4 ServerPlayer.isInvulnerableTo
holds while ``!hasClientLoaded()``, whatever the damage (``kill`` and the void included).

A client tells the server it has loaded the level (ServerboundPlayerLoadedPacket:
setClientLoaded(true)) within its first ticks; the emulator takes a player a client drives as
loaded at once. A PackTest dummy has no client: it waits for the timeout, 60 of its ticks
(Player.clientLoadedTimeoutTimer, counted down first thing in ServerPlayer.tick; 26.1 keeps it in
the connection: ServerGamePacketListenerImpl.tickClientLoadTimeout), from its spawn and from each
respawn (a new player).

- ``start(state, player)``: a player with no client joins (PackTest's ``dummy spawn|respawn``).
- ``tick(state)``: the timers count down; ``tick_is_idle(state)``: none is waiting.
- ``is_loading(state, player) -> bool``: its damage is refused.

Sources (decompiled 1.21.4 and 1.21.7: world/entity/player/Player.java (hasClientLoaded,
tickClientLoadTimeout, setClientLoaded), server/level/ServerPlayer.java (tick, isInvulnerableTo, die);
26.1.2: server/network/ServerGamePacketListenerImpl.java (hasClientLoaded); 1.21.3 has none of it).
"""
from __future__ import annotations

VERSION = (1, 21, 4)
TIMEOUT = 60


def start(state, player) -> None:
    if state.version >= VERSION:
        state.loading[player] = TIMEOUT


def tick_is_idle(state) -> bool:
    return not state.loading


def tick(state) -> None:
    if not state.loading:
        return
    for player, left in list(state.loading.items()):
        if left <= 1 or not player.alive:
            del state.loading[player]
        else:
            state.loading[player] = left - 1


def is_loading(state, player) -> bool:
    return bool(state.loading) and player in state.loading
