"""The layers of the code, read from every module's imports (parsed with ast, never imported).

Bottom up: the parser (mcfunction_parser) knows nothing of the emulator; the world library
(emulator/world) knows only the parser; the command implementations (emulator/commands) act on the
world; the runtime (emulator/runtime) runs ticks on a backend; the two backends (emulator/vm,
emulator/reference) build on the runtime and the commands but not on each other; the profile reads
the backends only through the runtime's declared hooks; the API, the PackTest runner and the CLI
sit on top; the pool game (poolgame) uses the emulator, which never imports it. No module imports
itself back through others.

An import inside a function counts as much as one at the top (it is a dependency all the same),
except the runtime's backend factory, which imports the backend it is asked for when asked.
"""
from __future__ import annotations

import ast
from dataclasses import dataclass
from functools import cache
from pathlib import Path


ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("mcfunction_parser", "emulator", "poolgame")

_PARSER = "mcfunction_parser"
_WORLD = ("emulator.world", _PARSER)
_COMMANDS = ("emulator.commands", *_WORLD)
_RUNTIME = ("emulator.runtime", *_COMMANDS)
_BACKENDS = ("emulator.vm", "emulator.reference", *_RUNTIME)
# what each part may import (a part is the longest prefix of a module's name listed here)
ALLOWED = {
    "mcfunction_parser": (_PARSER,),
    "emulator.world": _WORLD,
    "emulator.commands": _COMMANDS,
    "emulator.runtime": _RUNTIME,
    "emulator.vm": ("emulator.vm", *_RUNTIME),
    "emulator.reference": ("emulator.reference", *_RUNTIME),
    "emulator.profile": ("emulator.profile", *_RUNTIME),
    "emulator.api": ("emulator.profile", *_RUNTIME),
    "emulator.testing": ("emulator.testing", "emulator.api", "emulator.profile", *_BACKENDS),
    "emulator.cli": ("emulator.cli", "emulator.testing", "emulator.api", "emulator.profile", *_BACKENDS),
    "emulator": ("emulator.api", "emulator.cli"),  # the package itself and __main__
    "poolgame": ("poolgame", "emulator", _PARSER),
}
# (module, function) whose imports load a backend on demand
LAZY_FACTORIES = {("emulator.runtime.factory", "make_backend")}

@dataclass(frozen=True)
class Import:
    module: str  # the importing module
    target: str  # the module it imports
    line: int
    function: str | None  # the function the import is in, None at module level


@cache
def modules() -> dict[str, Path]:
    out = {}
    for package in PACKAGES:
        for path in sorted((ROOT / package).rglob("*.py")):
            parts = path.relative_to(ROOT).with_suffix("").parts
            out[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    return out


def _is_package(name: str) -> bool:
    return modules()[name].name == "__init__.py"


def _absolute(module: str, node: ast.ImportFrom) -> str:
    if not node.level:
        return node.module
    base = module.split(".") if _is_package(module) else module.split(".")[:-1]
    base = base[:len(base) - node.level + 1]
    return ".".join(base + ([node.module] if node.module else []))


def _targets(module: str, node: ast.Import | ast.ImportFrom) -> list[str]:
    """The project modules an import statement names (a name that is no module: its module)."""
    known = modules()
    if isinstance(node, ast.Import):
        names = [alias.name for alias in node.names]
    else:
        base = _absolute(module, node)
        names = [f"{base}.{alias.name}" if f"{base}.{alias.name}" in known else base for alias in node.names]
    return sorted({name for name in names if name in known})


class _Finder(ast.NodeVisitor):
    def __init__(self, module: str) -> None:
        self.module = module
        self.functions: list[str] = []
        self.found: list[Import] = []

    def _function(self, node) -> None:
        self.functions.append(node.name)
        self.generic_visit(node)
        self.functions.pop()

    visit_FunctionDef = visit_AsyncFunctionDef = _function

    def _import(self, node) -> None:
        function = self.functions[-1] if self.functions else None
        self.found += [Import(self.module, target, node.lineno, function) for target in _targets(self.module, node)]

    visit_Import = visit_ImportFrom = _import


@cache
def imports() -> tuple[Import, ...]:
    found = []
    for module, path in modules().items():
        finder = _Finder(module)
        finder.visit(ast.parse(path.read_text(), str(path)))
        found += [i for i in finder.found if i.target != module]
    return tuple(found)


def _within(name: str, prefix: str) -> bool:
    return name == prefix or name.startswith(prefix + ".")


def part_of(module: str) -> str:
    return max((p for p in ALLOWED if _within(module, p)), key=len)


def violations() -> set[tuple[str, str]]:
    out = set()
    for i in imports():
        if (i.module, i.function) in LAZY_FACTORIES:
            continue
        own = part_of(i.module)
        if not _within(i.target, own) and not any(_within(i.target, p) for p in ALLOWED[own]):
            out.add((i.module, i.target))
    return out


def test_every_module_belongs_to_a_part():
    assert all(part_of(m) for m in modules())


def test_no_import_runs_upward():
    found = violations()
    assert not found, "\n".join(f"{module} imports {target}" for module, target in sorted(found))


def test_the_backend_factory_imports_the_backends_lazily():
    lazy = [i for i in imports() if (i.module, i.function) in LAZY_FACTORIES]
    assert {i.target.split(".")[1] for i in lazy} == {"vm", "reference"}


def _graph() -> dict[str, set[str]]:
    """Module -> the modules importing it runs first: its targets, and their packages' ``__init__``
    outside the importer's own packages (importing ``a.b.c`` from elsewhere runs ``a.b`` first)."""
    graph: dict[str, set[str]] = {m: set() for m in modules()}
    for i in imports():
        own = {i.module.rsplit(".", n)[0] for n in range(i.module.count(".") + 1)}
        parts = i.target.split(".")
        packages = {".".join(parts[:n]) for n in range(1, len(parts))} - own
        graph[i.module] |= {i.target} | packages
    return graph


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan, iteratively)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    out = []
    for start in graph:
        if start in index:
            continue
        work = [(start, iter(sorted(graph[start])))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, edges = work[-1]
            step = next(edges, None)
            if step is not None:
                if step not in index:
                    index[step] = low[step] = len(index)
                    stack.append(step)
                    on_stack.add(step)
                    work.append((step, iter(sorted(graph[step]))))
                elif step in on_stack:
                    low[node] = min(low[node], index[step])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    out.append(sorted(component))
    return out


def test_no_import_cycle():
    cycles = _cycles(_graph())
    assert not cycles, "\n".join(" <-> ".join(c) for c in cycles)
