"""dpemu's emulator: run datapack functions tick by tick with the game's integer semantics.

``Emulator`` is imported on first use, so that ``dpemu --help`` (which imports this package before
its command line) loads neither the parser nor the world."""

__all__ = ["Emulator"]


def __getattr__(name: str):
    if name == "Emulator":
        from emulator.api import Emulator

        return Emulator
    raise AttributeError(f"module 'emulator' has no attribute {name!r}")
