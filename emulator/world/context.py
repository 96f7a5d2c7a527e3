"""Who runs a command and where, as the backends hand it around: the server or an entity, the
position, rotation, anchor and dimension."""
from __future__ import annotations

from dataclasses import dataclass

SERVER = -1  # executor index of the server (no entity)


@dataclass(slots=True)
class Context:
    """One command source: who runs it and where.

    ``executor`` is ``SERVER`` (-1) or the executing entity's ``Entity.order`` (its slot in the
    entity table, ``state.entities.table.handles``). ``pos`` is (x, y, z) doubles, ``rot`` (yaw, pitch) floats,
    ``anchor`` ``"feet"``/``"eyes"``.
    The server's default context is at world spawn (0, 0, 0 until ``setworldspawn``) in the overworld.
    """

    executor: int = SERVER
    pos: tuple[float, float, float] = (0.0, 0.0, 0.0)
    rot: tuple[float, float] = (0.0, 0.0)
    anchor: str = "feet"
    dimension: str = "minecraft:overworld"
