"""The linter behind ``dpemu check``: loader and parser diagnostics plus whole-pack rules.

Rules added here (the parser already reports syntax, unknown commands, literal ranges,
arguments against the game's command tree and version problems per command):
- a target release newer than every shipped command tree (warning, once: its commands are
  checked against the newest tree, their findings warnings; see :mod:`.gamedata`);
- a ``function``, ``schedule function``, ``execute if function`` or advancement reward naming a
  function or function tag that is not loaded (error; a tag the game refused to load is named as
  such);
- ``execute if predicate`` or a selector's ``predicate=`` naming a predicate file that is not
  loaded (error);
- ``loot`` or ``item modify`` naming a loot table or item modifier that is not loaded, ``recipe``
  naming a recipe that is not, an
  advancement's ``rewards.loot`` or ``rewards.recipes`` naming a loot table or recipe that is not
  (error in a namespace the packs define, warning in another; ``minecraft:`` only with a game jar);
- calling a macro function without arguments (directly, by ``schedule``, or as a member of
  ``#minecraft:load``/``#minecraft:tick``), or with a literal compound that lacks one of its
  ``$(keys)`` (error: the game fails the call);
- ``execute if|unless function`` on functions that contain no ``return`` (warning: the condition
  fails both ways when no function returned);
- an objective used but never created by ``scoreboard objectives add`` in the loaded packs
  (warning, once per objective);
- a function nothing refers to: not in a tag, not called or scheduled by another function, not
  an advancement reward (info).
"""
from __future__ import annotations

import dataclasses
import functools
import re
import time
import typing
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path

from . import ast, gamedata
from .diagnostics import ERROR, INFO, WARNING, Diagnostic, Loc
from mcfunction_parser.pack import conditions, loot as loot_files
from mcfunction_parser.pack.text import json_document
from mcfunction_parser.pack.loader import LoadedPacks, load_packs
from mcfunction_parser.parse import paused_gc
from mcfunction_parser.pack.versions import RELEASE_FORMATS, Version, parse_mc_version, releases_label, version_label

# Function references and objective definitions inside macro templates (unparsed until called).
_MACRO_FUNCTION = re.compile(r"(?:^|\s)function\s+(#?[a-z0-9_.-]+:[a-z0-9_./-]+)(?=\s|$)")
_RESOURCE_LOCATION = re.compile(r"[a-z0-9_.-]+:[a-z0-9_./-]+")
_MACRO_OBJECTIVE_ADD = re.compile(r"(?:^|\s)scoreboard\s+objectives\s+add\s+(\S+)")


@dataclass
class CheckResult:
    loaded: LoadedPacks
    diagnostics: list[Diagnostic]  # loader, parser and linter findings, by file and position
    seconds: float
    checked: tuple[str, ...] = ()  # the releases checked, when more than the packs' own one

    @property
    def files(self) -> int:
        return self.loaded.files

    def _parsed(self) -> list:
        """Every function file parsed, those the game refuses included."""
        return [*self.loaded.functions.values(), *self.loaded.refused.values()]

    @property
    def functions(self) -> int:
        return len(self._parsed())

    @property
    def commands(self) -> int:
        return sum(len(f.commands) for f in self._parsed())

    @property
    def lines(self) -> int:
        return sum(f.lines for f in self._parsed())

    def of(self, severity: str) -> list[Diagnostic]:
        return [d for d in self.diagnostics if d.severity == severity]

    def summary(self) -> str:
        errors, warnings = len(self.of(ERROR)), len(self.of(WARNING))
        releases = f" (checked for {releases_label([parse_mc_version(v) for v in self.checked])})" if self.checked else ""
        return (f"{_count(self.files, 'file')}, {_count(self.functions, 'function')}, "
                f"{_count(self.commands, 'command')}: {_count(errors, 'error')}, "
                f"{_count(warnings, 'warning')}{releases}")

    def to_json(self) -> dict:
        return {"files": self.files, "functions": self.functions, "commands": self.commands,
                "lines": self.lines,
                "errors": [d.to_json() for d in self.of(ERROR)],
                "warnings": [d.to_json() for d in self.of(WARNING)],
                "infos": [d.to_json() for d in self.of(INFO)],
                "versions": list(self.checked) or [version_label(self.loaded.version)],
                "seconds": round(self.seconds, 3)}


def _count(n: int, noun: str) -> str:
    return f"{n} {noun}{'' if n == 1 else 's'}"


def check_packs(paths: Sequence[str | Path], mc_version: str | None = None,
                with_packs: Sequence[str | Path] = (), workers: int | None = None,
                on_function=None, game_jar: str | Path | None = None) -> CheckResult:
    """Load the packs (in order) and lint them. ``mc_version`` and ``workers`` as for
    :func:`load_packs`. ``with_packs``: packs expected beside them at run time (libraries, other
    modules), loaded first; their own findings are not reported. ``on_function`` as for
    :func:`load_packs`."""
    start = time.perf_counter()
    with paused_gc(kept=True):  # the packs' ASTs hold no reference cycles
        loaded = load_packs([*with_packs, *paths], mc_version, workers, on_function, game_jar=game_jar)
        found = lint(loaded)
        diagnostics = sorted(loaded.diagnostics + found, key=_position)
    if with_packs:
        beside = tuple(str(Path(p)).rstrip("/") + "/" for p in with_packs)
        diagnostics = [d for d in diagnostics if not (d.path + "/").startswith(beside)]
    return CheckResult(loaded, diagnostics, time.perf_counter() - start)


def check_releases(paths: Sequence[str | Path], releases: Sequence[Version] | None = None,
                   with_packs: Sequence[str | Path] = (), workers: int | None = None,
                   on_function=None, game_jar: str | Path | None = None) -> CheckResult:
    """Lint the packs once per data pack format among ``releases`` (each format's newest release
    stands for it: the parser's rules follow the format) and merge the findings: one true in every
    release as it is, one true in some tagged with those releases. ``releases`` None: the range
    every pack declares (``supported_formats``, ``min_format``/``max_format``), else the packs' own
    release as :func:`check_packs` picks it. ``workers`` as for :func:`load_packs`."""
    if releases is None:
        first = check_packs(paths, with_packs=with_packs, workers=workers, on_function=on_function, game_jar=game_jar)
        releases = declared_releases(first.loaded)
        if len({RELEASE_FORMATS[v] for v in releases}) < 2:
            return first
    by_format: dict = {}
    for release in sorted(releases):
        by_format[RELEASE_FORMATS[release]] = release
    if len(by_format) == 1:
        return check_packs(paths, version_label(max(releases)), with_packs, workers, on_function, game_jar)
    results = [(fmt, check_packs(paths, version_label(release), with_packs, workers, on_function, game_jar))
               for fmt, release in by_format.items()]
    return _merged(results, releases)


def declared_releases(loaded: LoadedPacks) -> list[Version]:
    """The known releases whose format every loaded pack declares it supports (none declared: [])."""
    ranges = [p.supported for p in loaded.packs if p.supported is not None]
    if not ranges:
        return []
    return sorted(v for v, fmt in RELEASE_FORMATS.items() if all(fmt in r for r in ranges))


# The part of a message that names the release it was checked for ("(pack targets 1.18.2)", "not
# 1.20.4 (format 26)"): dropped when one finding stands for several releases.
_CHECKED_RELEASE = re.compile(r" \(pack targets [0-9.]+\)|, not [0-9.]+ \(format [0-9.]+\)")


def _merged(results: list, releases: Sequence[Version]) -> CheckResult:
    """One result from per-format ones: the newest format's counts, every finding once."""
    held: dict[tuple, tuple[Diagnostic, set]] = {}
    for fmt, result in results:
        for d in result.diagnostics:
            d = dataclasses.replace(d, message=_CHECKED_RELEASE.sub("", d.message))
            key = (d.severity, d.message, d.path, d.line, d.col)
            held.setdefault(key, (d, set()))[1].add(fmt)
    all_formats = {fmt for fmt, _ in results}
    merged = []
    for d, formats in held.values():
        if formats != all_formats:
            d = dataclasses.replace(d, versions=tuple(version_label(v) for v in sorted(releases)
                                                      if RELEASE_FORMATS[v] in formats))
        merged.append(d)
    newest = results[-1][1]
    return CheckResult(newest.loaded, sorted(merged, key=_position), sum(r.seconds for _, r in results),
                       checked=tuple(version_label(v) for v in sorted(releases)))


def _position(d: Diagnostic) -> tuple:
    return (d.path, d.line or 0, d.col or 0)


def lint(loaded: LoadedPacks) -> list[Diagnostic]:
    """The whole-pack rules above, as new diagnostics."""
    found: list[Diagnostic] = []
    _check_game_data(loaded, found)
    facts = _gather(loaded)
    _check_calls(loaded, facts, found)
    _check_predicates(loaded, facts, found)
    _check_resources(loaded, facts, found)
    _check_objectives(loaded, facts, found)
    _check_unreferenced(loaded, facts, found)
    return found


# ----------------------------------------------------------------------------- walking the AST


def walk(node: object, out: list[object]) -> None:
    """Append every AST node inside ``node`` (itself included) to ``out``, in source order."""
    out.append(node)
    for name in _child_fields(type(node)):
        value = getattr(node, name)
        if type(value) is tuple:
            for item in value:
                if hasattr(item, "__dataclass_fields__"):
                    walk(item, out)
        elif hasattr(value, "__dataclass_fields__"):
            walk(value, out)


# Nodes whose insides never hold a command, a selector or an objective: not walked into.
_LEAVES = (ast.Vec3, ast.Vec2, ast.Coord, ast.IntRange, ast.FloatRange, ast.NbtPath, ast.StorageData)


@functools.cache
def _child_fields(cls: type) -> tuple[str, ...]:
    """Field names that may hold nodes (not ``loc``, not plain values), cached per class."""
    if issubclass(cls, _LEAVES):
        return ()
    plain = ("str", "int", "bool", "float", "str | None", "int | None", "float | None", "bool | None")
    return tuple(f.name for f in dataclasses.fields(cls) if f.name != "loc" and str(f.type) not in plain)


# ----------------------------------------------------------------------------- what the rules read


@dataclass
class _Facts:
    """What the rules read from the functions' ASTs, gathered in one walk, in the order of
    :func:`walk` (function by function, each node before the nodes inside it)."""

    calls: list[tuple[ast.Function, object]] = field(default_factory=list)  # nodes naming functions
    returning: set[str] = field(default_factory=set)  # functions with a return or a macro line
    predicates: list[tuple[str, Loc]] = field(default_factory=list)  # predicate named, where
    created: set[str] = field(default_factory=set)  # objectives added (by macro lines too)
    uses: dict[str, list[Loc]] = field(default_factory=dict)  # objective -> where used, in order
    resources: list[tuple[str, str, Loc]] = field(default_factory=list)  # (loot_table|item_modifier, id, where)
    inline: list[tuple[str, typing.Any, Loc]] = field(default_factory=list)  # (loot table|item modifier, its JSON, where)

    def use(self, objective: str, loc: Loc) -> None:
        self.uses.setdefault(objective, []).append(loc)


def _gather(loaded: LoadedPacks) -> _Facts:
    facts = _Facts()
    for function in [*loaded.functions.values(), *loaded.refused.values()]:  # refused ones too
        for command in function.commands:
            _visit(command, function, facts)
    return facts


def _visit(node: object, function: ast.Function, facts: _Facts) -> None:
    """Record what ``node`` and the nodes inside it tell the rules."""
    record, fields = _plan(type(node))
    if record is not None:
        record(node, function, facts)
    for name in fields:
        value = getattr(node, name)
        if type(value) is tuple:
            for item in value:
                _visit(item, function, facts)
        elif value is not None:
            _visit(value, function, facts)


@functools.cache
def _plan(cls: type) -> tuple[Callable | None, tuple[str, ...]]:
    """What :func:`_visit` records of a node class, and the fields it looks inside: those whose
    declared type may hold a node the rules read (``Vec3``, ``NbtPath``, names... never do)."""
    hints = typing.get_type_hints(cls)
    return _record_for(cls), tuple(f.name for f in dataclasses.fields(cls) if _may_hold_facts(hints[f.name]))


def _may_hold_facts(hint: object) -> bool:
    if isinstance(hint, type):
        return dataclasses.is_dataclass(hint) and _holds_facts(hint)
    return any(_may_hold_facts(arg) for arg in typing.get_args(hint))  # unions, tuple[X, ...]


@functools.cache
def _holds_facts(cls: type) -> bool:
    if issubclass(cls, (ast.Command, ast.Subcommand)):  # any command may be, or hold, any other
        return True
    hints = typing.get_type_hints(cls)
    return _record_for(cls) is not None or any(_may_hold_facts(hints[f.name]) for f in dataclasses.fields(cls))


def _record_for(cls: type) -> Callable | None:
    for base in cls.__mro__:
        if base in _RECORDS:
            return _RECORDS[base]
    objectives = tuple(f.name for f in dataclasses.fields(cls) if f.name in ("objective", "source_objective"))
    return _objective_uses(objectives) if objectives else None


def _record_call(node: object, function: ast.Function, facts: _Facts) -> None:
    facts.calls.append((function, node))


def _record_macro_line(node: ast.MacroLine, function: ast.Function, facts: _Facts) -> None:
    facts.calls.append((function, node))
    facts.returning.add(function.id)  # a macro line may return too
    facts.created.update(m.group(1) for m in _MACRO_OBJECTIVE_ADD.finditer(node.template))


def _record_return(node: ast.Return, function: ast.Function, facts: _Facts) -> None:
    facts.returning.add(function.id)


def _record_if_predicate(node: ast.IfPredicate, function: ast.Function, facts: _Facts) -> None:
    facts.predicates.append((node.predicate, node.loc))


def _record_selector_arg(node: ast.SelectorArg, function: ast.Function, facts: _Facts) -> None:
    if node.key == "predicate":
        facts.predicates.append((node.value, node.loc))
    elif node.key == "scores":
        for objective, _ in node.value:
            facts.use(objective, node.loc)


def _record_objective_add(node: ast.ObjectivesAdd, function: ast.Function, facts: _Facts) -> None:
    facts.created.add(node.objective)


def _objective_uses(names: tuple[str, ...]) -> Callable:
    """The record of a node class whose fields ``names`` name objectives it uses."""
    def record(node: object, function: ast.Function, facts: _Facts) -> None:
        for name in names:
            objective = getattr(node, name)
            if isinstance(objective, str):
                facts.use(objective, node.loc)
    return record


def _record_resources(node: ast.Command, function: ast.Function, facts: _Facts) -> None:
    """Loot tables and item modifiers named by id, and the inline ones (1.20.5+)."""
    table = node.table if isinstance(node, ast.Loot) else None
    for kind, found in (("loot table", table), ("item modifier", getattr(node, "modifier", None))):
        if found is not None and found.id is not None:
            facts.resources.append((kind, found.id, node.loc))
        elif found is not None and found.inline is not None:
            facts.inline.append((kind, found.inline, node.loc))


def _record_recipe(node: ast.GenericCommand, function: ast.Function, facts: _Facts) -> None:
    """``recipe give|take TARGETS RECIPE``: the recipe, looked up when the command runs."""
    words = node.text.split()
    if node.name == "recipe" and len(words) >= 4 and words[-1] != "*":
        name = words[-1] if ":" in words[-1] else "minecraft:" + words[-1]
        facts.resources.append(("recipe", name, node.loc))


_RECORDS: dict[type, Callable] = {
    ast.FunctionCall: _record_call, ast.Schedule: _record_call, ast.IfFunction: _record_call,
    ast.MacroLine: _record_macro_line, ast.Return: _record_return, ast.IfPredicate: _record_if_predicate,
    ast.SelectorArg: _record_selector_arg, ast.ObjectivesAdd: _record_objective_add,
    ast.Loot: _record_resources, ast.ItemModify: _record_resources, ast.ItemReplace: _record_resources,
    ast.GenericCommand: _record_recipe,
}


def _at(loaded: LoadedPacks, severity: str, message: str, loc: Loc) -> Diagnostic:
    lines = loaded.sources.get(loc.path, [])
    source = lines[loc.line - 1] if 0 < loc.line <= len(lines) else None
    return Diagnostic.at(severity, message, loc, source)


# ----------------------------------------------------------------------------- rules


def _check_game_data(loaded: LoadedPacks, found: list[Diagnostic]) -> None:
    """A release checked against another minor release's command tree (1.13 – 1.15, 26.x) gets
    its findings as warnings: said once, naming the tree used and how to get that release's own."""
    note = gamedata.stand_in(loaded.version)
    if note is not None:
        path = str(loaded.packs[-1].root) if loaded.packs else ""
        found.append(Diagnostic(WARNING, note, path))


def _references(node: object) -> Iterator[tuple[str, bool, str]]:
    """(id, is_tag, how) for each function reference a node makes."""
    if isinstance(node, ast.FunctionCall):
        yield node.function, node.is_tag, "function"
    elif isinstance(node, ast.Schedule):
        yield node.function, node.is_tag, "schedule function"
    elif isinstance(node, ast.IfFunction):
        yield node.function, node.is_tag, "execute if function"
    elif isinstance(node, ast.MacroLine):  # ids with a $(placeholder) do not match the pattern
        for match in _MACRO_FUNCTION.finditer(node.template):
            name = match.group(1)
            yield name.removeprefix("#"), name.startswith("#"), "macro"


def _check_calls(loaded: LoadedPacks, facts: _Facts, found: list[Diagnostic]) -> None:
    defined = _namespaces(loaded)
    for _, node in facts.calls:
        for name, is_tag, how in _references(node):
            if how != "macro":
                problem = _missing(loaded, name, is_tag)
                if problem:
                    where = "" if how == "function" else f" ({how})"
                    found.append(_reference_problem(loaded, problem + where, name, defined, node.loc))
        if isinstance(node, ast.FunctionCall) and not node.is_tag and node.with_source is None:
            _check_macro_arguments(loaded, node, found)
        elif isinstance(node, ast.IfFunction):
            _check_condition_returns(loaded, node, facts.returning, found)
        elif isinstance(node, ast.Schedule) and not node.is_tag and _is_macro(loaded, node.function):
            found.append(_at(loaded, ERROR, f"function {node.function} is a macro function: a "
                             "scheduled call has no arguments and fails", node.loc))
    _check_game_tags(loaded, found)
    for function_id, locs in loaded.advancement_rewards.items():
        if function_id not in loaded.functions:
            found.extend(_reference_problem(loaded, f"unknown function {function_id} (advancement reward)",
                                            function_id, defined, loc) for loc in locs)


def _namespaces(loaded: LoadedPacks) -> set[str]:
    """The namespaces the loaded packs define functions, function tags, predicates, loot tables or
    item modifiers in."""
    ids = [*loaded.functions, *loaded.refused, *loaded.tags, *loaded.failed_tags, *loaded.predicates,
           *loaded.loot_tables, *loaded.item_modifiers]
    return {i.split(":", 1)[0] for i in ids}


def _reference_problem(loaded: LoadedPacks, problem: str, name: str, defined: set[str], loc: Loc,
                       when: str = "the call fails when it runs") -> Diagnostic:
    """A reference to a function, tag or other file that is not loaded. The game loads the function
    anyway and looks the id up when the command runs (FunctionArgument.parse reads only the id;
    Result.create looks it up; a selector's ``predicate=`` is looked up per entity): an error when
    the namespace is one the packs define (a typo, most likely), a warning when no loaded pack
    defines the namespace (a pack expected beside this one: name it with --with)."""
    namespace = name.split(":", 1)[0]
    if namespace in defined:
        return _at(loaded, ERROR, problem, loc)
    return _at(loaded, WARNING, f"{problem}: no loaded pack defines the namespace '{namespace}' ({when} "
               "unless a pack beside this one defines it; name that pack with --with)", loc)


def _is_macro(loaded: LoadedPacks, function_id: str) -> bool:
    function = loaded.functions.get(function_id)
    return function is not None and function.is_macro


def _check_game_tags(loaded: LoadedPacks, found: list[Diagnostic]) -> None:
    """The game runs ``#minecraft:load`` and ``#minecraft:tick`` members without arguments."""
    for tag_id in ("minecraft:load", "minecraft:tick"):
        for function_id in loaded.resolve_tag(tag_id):
            if _is_macro(loaded, function_id):
                found.append(Diagnostic(ERROR, f"function {function_id} is a macro function: as a "
                                        f"member of #{tag_id} it runs without arguments and fails",
                                        loaded.functions[function_id].path))


def _check_macro_arguments(loaded: LoadedPacks, call: ast.FunctionCall, found: list[Diagnostic]) -> None:
    """The game instantiates a macro function only when every ``$(key)`` of every line is given."""
    if not _is_macro(loaded, call.function):
        return
    callee = loaded.functions[call.function]
    if call.arguments is None:
        found.append(_at(loaded, ERROR, f"function {call.function} is a macro function: calling it "
                         "without arguments fails", call.loc))
        return
    keys = dict.fromkeys(k for c in callee.commands if isinstance(c, ast.MacroLine) for k in c.keys)
    missing = [k for k in keys if k not in call.arguments]
    if missing:
        found.append(_at(loaded, ERROR, f"function {call.function} needs macro argument(s) "
                         f"{', '.join(missing)}: the call fails without them", call.loc))


def _check_condition_returns(loaded: LoadedPacks, condition: ast.IfFunction, returning: set[str],
                             found: list[Diagnostic]) -> None:
    """``execute if|unless function`` fails both ways when no called function returns a value."""
    if condition.is_tag:
        members = loaded.resolve_tag(condition.function) if condition.function in loaded.tags else []
    else:
        members = [condition.function] if condition.function in loaded.functions else []
    if members and not any(m in returning for m in members):
        what = f"#{condition.function}" if condition.is_tag else condition.function
        found.append(_at(loaded, WARNING, f"{what} never runs 'return', so 'execute "
                         f"{'unless' if condition.negated else 'if'} function' always fails",
                         condition.loc))


def _missing(loaded: LoadedPacks, name: str, is_tag: bool) -> str | None:
    if not is_tag:
        if name in loaded.refused:
            return f"function {name} fails to load (a line of it does not parse), so it is unknown to the game"
        return None if name in loaded.functions else f"unknown function {name}"
    if name in loaded.tags:
        return None
    if name in loaded.failed_tags:
        return f"function tag #{name} fails to load ({loaded.failed_tags[name].reason})"
    return f"unknown function tag #{name}"


def _check_predicates(loaded: LoadedPacks, facts: _Facts, found: list[Diagnostic]) -> None:
    """``execute if predicate ID`` and ``@e[predicate=ID]`` need a predicate file (the vanilla
    pack defines none); an inline ``{...}`` predicate (1.20.5+) must be one the game loads."""
    defined = _namespaces(loaded)
    for name, loc in facts.predicates:
        if name[:1] in "{[":
            try:
                problem = conditions.problem(conditions.parse_inline(name), loaded.version)
            except ValueError as error:
                problem = (f"does not parse: {error}", "")
            if problem:
                found.append(_at(loaded, ERROR, f"inline predicate: {problem[0]}", loc))
        elif _RESOURCE_LOCATION.fullmatch(name) and name not in loaded.predicates:
            # EntitySelectorOptions "predicate": an unknown id matches no entity; `execute if
            # predicate` fails (ResourceOrIdArgument.getPredicate)
            found.append(_reference_problem(loaded, f"unknown predicate {name}", name, defined, loc,
                                            "it is unknown when it runs"))


def _check_resources(loaded: LoadedPacks, facts: _Facts, found: list[Diagnostic]) -> None:
    """A loot table, item modifier or recipe must be loaded (the command fails when it runs), and so must
    the loot tables and recipes of advancement rewards: an error in a namespace the loaded packs
    define, a warning in another; the game's own (``minecraft:``) tables and recipes come only with
    --game-jar, so those are not judged without it."""
    for kind, value, loc in facts.inline:  # ResourceOrIdArgument decodes it as the file's codec does
        problems: list[Diagnostic] = []
        check = loot_files.check_loot_table if kind == "loot table" else loot_files.check_modifier
        check(json_document(value, "<inline>"), loaded.version, problems)
        found.extend(_at(loaded, ERROR, f"inline {kind}: {p.message}", loc) for p in problems if p.severity == ERROR)
    defined = (_namespaces(loaded) | {r.split(":", 1)[0] for r in loaded.recipes}) - {"minecraft"}
    loaded_ids = {"loot table": loaded.loot_tables, "item modifier": loaded.item_modifiers, "recipe": loaded.recipes}
    for kind, name, loc in facts.resources:
        if name not in loaded_ids[kind] and not name.startswith("minecraft:"):
            found.append(_reference_problem(loaded, f"unknown {kind} {name}", name, defined, loc,
                                            "the command fails when it runs"))
    # AdvancementRewards.grant: an unknown table gives nothing (LootTable.EMPTY), an unknown recipe
    # is skipped (ServerPlayer.awardRecipesByKey), both in silence
    defined |= {"minecraft"} if loaded.vanilla_data else set()
    for kind, named, known in (("loot table", loaded.advancement_loot, loaded.loot_tables),
                               ("recipe", loaded.advancement_recipes, loaded.recipes)):
        for name, locs in named.items():
            if name not in known and (loaded.vanilla_data or not name.startswith("minecraft:")):
                found.extend(_reference_problem(loaded, f"unknown {kind} {name} (advancement reward)", name, defined,
                                                loc, "the reward gives nothing when it is earned") for loc in locs)


def _check_objectives(loaded: LoadedPacks, facts: _Facts, found: list[Diagnostic]) -> None:
    for objective, locs in facts.uses.items():
        if objective not in facts.created:
            more = f" ({len(locs)} uses)" if len(locs) > 1 else ""
            found.append(_at(loaded, WARNING, f"objective '{objective}' is used but never created by "
                             f"'scoreboard objectives add' in the loaded packs{more}", locs[0]))


def _check_unreferenced(loaded: LoadedPacks, facts: _Facts, found: list[Diagnostic]) -> None:
    referenced = set(loaded.advancement_rewards)
    tags = [*loaded.tags.values(), *(failed.tag for failed in loaded.failed_tags.values())]
    for tag in tags:
        referenced.update(e.id for e in tag.entries if not e.is_tag)
    for function, node in facts.calls:
        for name, is_tag, _ in _references(node):
            if not is_tag and name != function.id:
                referenced.add(name)
    for fid, function in loaded.functions.items():
        if fid not in referenced:
            found.append(Diagnostic(INFO, f"function {fid} is never referenced (no tag, function, "
                                    "schedule or advancement reward names it)", function.path))
