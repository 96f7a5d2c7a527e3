"""Parse and check Minecraft Java Edition data packs: pack loading, the command parser, diagnostics."""
from .diagnostics import Diagnostic, Loc
from mcfunction_parser.pack.loader import LoadedPacks, PackInfo, load_packs
from .parse import parse_command, parse_function

__all__ = ["Diagnostic", "LoadedPacks", "Loc", "PackInfo", "load_packs", "parse_command", "parse_function"]
