"""dpemu's emulator: run datapack functions tick by tick with the game's integer semantics."""
from emulator.api import Emulator

__all__ = ["Emulator"]
