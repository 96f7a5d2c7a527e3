"""Build ``NbtPath`` AST values for tests without depending on the command parser."""
from __future__ import annotations

from mcfunction_parser import ast
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.nbt import Compound

LOC = Loc("test.mcfunction", 1, 1)


def path(text: str, *nodes) -> ast.NbtPath:
    """``path("a.b[0]", "a", "b", 0)``: str -> key, int -> index, "[]" -> all, dict -> filter
    (root or after a key), ``[dict]`` -> list match."""
    built = []
    for node in nodes:
        if node == "[]":
            built.append(ast.PathAll())
        elif isinstance(node, str):
            built.append(ast.PathKey(node))
        elif isinstance(node, int):
            built.append(ast.PathIndex(node))
        elif isinstance(node, dict):
            built.append(ast.PathFilter(Compound(node)))
        elif isinstance(node, list):
            built.append(ast.PathMatch(node[0]))
    return ast.NbtPath(tuple(built), text, LOC)
