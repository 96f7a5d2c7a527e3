"""Parse and check Minecraft Java Edition data packs: pack loading, the command parser, diagnostics."""
from .diagnostics import Diagnostic, Loc
from .pack import LoadedPacks, PackInfo, load_packs

__all__ = ["Diagnostic", "LoadedPacks", "Loc", "PackInfo", "load_packs"]
