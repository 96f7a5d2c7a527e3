"""What the world's level data keeps besides time and weather: the world spawn, the difficulty, the
default game mode and the world border (one for every level: the other levels follow the
overworld's, WorldBorder.DelegateBorderChangeListener).

Defaults: a new world's spawn here is (0, 0, 0) with angle 0 (the emulator generates no terrain to
search for one); difficulty ``normal`` and game mode ``survival`` (a new world's LevelSettings);
the border WorldBorder's defaults (size 5.999997E7, centre 0 0, 0.2 damage per block past a 5 block
buffer, a 15 s / 5 block warning).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

DIFFICULTIES = ("peaceful", "easy", "normal", "hard")  # Difficulty.getId is the index
MAX_BORDER_SIZE = float(np.float32(5.999997e7))  # WorldBorder.MAX_SIZE, a float widened to double


@dataclass
class LevelSettings:
    spawn: tuple[int, int, int] = (0, 0, 0)
    spawn_angle: np.float32 = np.float32(0.0)
    difficulty: str = "normal"
    default_gamemode: str = "survival"
    border_size: float = MAX_BORDER_SIZE
    border_center: tuple[float, float] = (0.0, 0.0)
    border_damage_per_block: float = 0.2
    border_damage_buffer: float = 5.0
    border_warning_time: int = 15
    border_warning_blocks: int = 5
    _position: tuple = field(default=(None, None), repr=False, compare=False)  # (spawn, its position)

    def server_position(self) -> tuple[float, float, float]:
        """Where the server's command source stands (MinecraftServer.createCommandSourceStack:
        Vec3.atLowerCornerOf(the world spawn), rotation 0 0): the ``#load``/``#tick`` and scheduled
        functions' position (asked for at every root: worked out again only when the spawn moved)."""
        if self._position[0] is not self.spawn:
            self._position = (self.spawn, tuple(float(v) for v in self.spawn))
        return self._position[1]
