"""Jukeboxes playing their songs (1.21+: JukeboxSongPlayer).

- ``tick(state, blocks, pos, nbt)``: JukeboxBlockEntity.tick: a jukebox that plays a song (its
  ``RecordItem`` has a ``jukebox_playable`` song and ``ticks_since_song_started`` is saved, as a
  long) counts the ticks up; once they reach the song's length in ticks plus 20 it stops
  (the key is no longer saved; the record stays). A jukebox holding anything else does nothing.
- ``idle(state, nbt) -> bool``: nothing plays.
- ``item_set(nbt, stack, version)``: JukeboxBlockEntity.setTheItem (item commands): a song's disc
  starts playing from tick 0, anything else stops it.

A block placed or changed with NBT plays only when that NBT has ``ticks_since_song_started``
(loadAdditional). Song lengths are the game's own (JukeboxSongs, in seconds; lengthInTicks is
ceil(seconds x 20)); a song a pack defines in ``jukebox_song`` is not modelled. Not modelled either:
the comparator output and redstone signal while playing, the JUKEBOX_PLAY game event and particles.
Before 1.21 (RecordItem with IsPlaying, RecordStartTick and TickCount) playing is not modelled.

Sources (decompiled 1.21): world/level/block/entity/JukeboxBlockEntity.java (tick, loadAdditional,
saveAdditional, setTheItem), world/item/JukeboxSongPlayer.java (play, stop, tick),
world/item/JukeboxSong.java (lengthInTicks, hasFinished, fromStack), world/item/JukeboxSongs.java.
"""
from __future__ import annotations

import math

from emulator.world.errors import Unmodelled
from emulator.world.items import ItemStack, from_nbt
from mcfunction_parser.nbt import Compound, Long, String

SONG_PLAYER_VERSION = (1, 21)
TICKS = "ticks_since_song_started"
# JukeboxSongs.bootstrap: the length of each song in seconds
_LENGTHS = {"13": 178, "cat": 185, "blocks": 345, "chirp": 185, "far": 174, "mall": 197, "mellohi": 96, "stal": 150,
            "strad": 188, "ward": 251, "11": 71, "wait": 238, "pigstep": 149, "otherside": 195, "5": 178,
            "relic": 218, "precipice": 299, "creator": 176, "creator_music_box": 73}
_LENGTHS = {f"minecraft:{song}": seconds for song, seconds in _LENGTHS.items()}


def song_of(stack: ItemStack) -> str | None:
    """JukeboxSong.fromStack: the song of the stack's ``jukebox_playable`` component, or None."""
    if stack.is_empty:
        return None
    playable = stack.component("minecraft:jukebox_playable")
    if not isinstance(playable, Compound):
        return None
    song = playable.get("song")
    if not isinstance(song, String):
        raise Unmodelled("a jukebox playing a song defined inline")
    return str(song) if ":" in str(song) else f"minecraft:{song}"


def length_in_ticks(song: str) -> int:
    if song not in _LENGTHS:
        raise Unmodelled(f"a jukebox playing {song} (songs a pack defines are not modelled)")
    return math.ceil(_LENGTHS[song] * 20.0)


def _playing(nbt) -> str | None:
    record = nbt.get("RecordItem")
    if not isinstance(nbt.get(TICKS), Long) or not isinstance(record, Compound):
        return None
    return song_of(from_nbt(record))


def tick(state, blocks, pos, nbt) -> None:
    """JukeboxSongPlayer.tick: stopped once hasFinished (ticks >= length + 20), else one more tick."""
    if tuple(state.version) < SONG_PLAYER_VERSION:
        if nbt.get("RecordItem"):
            raise Unmodelled("a jukebox playing before 1.21")
        return
    song = _playing(nbt)
    if song is None:
        return
    ticks = int(nbt[TICKS])
    if ticks >= length_in_ticks(song) + 20:
        del nbt[TICKS]
    else:
        nbt[TICKS] = Long(ticks + 1)


def idle(state, nbt) -> bool:
    if tuple(state.version) < SONG_PLAYER_VERSION:
        return not nbt.get("RecordItem")
    return _playing(nbt) is None


def item_set(nbt, stack: ItemStack, version) -> None:
    """setTheItem: a disc with a song plays from 0 (JukeboxSongPlayer.play), else it stops."""
    if tuple(version) < SONG_PLAYER_VERSION:
        return
    if song_of(stack) is not None:
        nbt[TICKS] = Long(0)
    else:
        nbt.pop(TICKS, None)
