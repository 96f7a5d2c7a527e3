"""Runners that execute pool datapack functions for the tests.

`MiniScoreboard` interprets only the command subset the pool datapack's physics uses, with the
Java semantics of `emulator.semantics`: scoreboard players set/add/remove/operation/get,
`execute as|if|unless|store result entity ... run`, `function` (with macro arguments), `return`,
`tag`, and entities reduced to named score holders with tags, a position and a rotation
(`@s[..]`, `@e[tag=..,scores={..},limit=..]`, `@a[..]` for the entities marked as players;
no summon). It is the stepping stone used until `emulator.Emulator` runs
entities; the math tests run on every runner available. Any int32 wrap raises `Overflow`.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

from emulator.semantics import floor_div, floor_mod, wrap32

from pack_paths import PACK

_OPS = {"/=": floor_div, "%=": floor_mod, "=": lambda a, b: b, "<": min, ">": max,
        "+=": int.__add__, "-=": int.__sub__, "*=": int.__mul__}
_CMP = {"<": int.__lt__, "<=": int.__le__, "=": int.__eq__, ">=": int.__ge__, ">": int.__gt__}
_MACRO_ARGUMENT = re.compile(r'(\w+):("([^"]*)"|[^,}]+)')
_MACRO_VARIABLE = re.compile(r"\$\((\w+)\)")


class Overflow(AssertionError):
    """An operation wrapped: the datapack promises it never does."""


@dataclass
class Entity:
    name: str                      # its score holder name
    tags: set = field(default_factory=set)
    pos: list = field(default_factory=lambda: [0.0, 0.0, 0.0])
    rotation: list = field(default_factory=lambda: [0.0, 0.0])
    player: bool = False


def _in_range(value: int | None, text: str) -> bool:
    if value is None:
        return False
    low, dots, high = text.partition("..")
    if not dots:
        return value == int(low)
    return (not low or value >= int(low)) and (not high or value <= int(high))


class MiniScoreboard:
    name = "mini"

    def __init__(self) -> None:
        self.scores: dict[tuple[str, str], int] = {}
        self.entities: list[Entity] = []
        self.messages: list[str] = []
        self.commands = 0
        self._cache: dict[str, list[str]] = {}
        self.call("pool:load")

    # ------------------------------------------------------------------ API
    def set_score(self, holder: str, objective: str, value: int) -> None:
        self.scores[holder, objective] = value

    def score(self, holder: str, objective: str) -> int:
        return self.scores[holder, objective]

    def add_entity(self, name: str, *tags: str, player: bool = False) -> Entity:
        entity = Entity(name, set(tags), player=player)
        self.entities.append(entity)
        return entity

    def call(self, function: str, as_: str | None = None, arguments: dict | None = None) -> None:
        """Run ``function`` as the fake player or entity named ``as_`` (what ``@s`` stands for)."""
        self._run(function, as_, arguments or {})

    # ------------------------------------------------------------------ functions
    def _lines(self, function: str) -> list[str]:
        if function not in self._cache:
            namespace, path = function.split(":")
            text = (PACK / "data" / namespace / "function" / f"{path}.mcfunction").read_text()
            self._cache[function] = [line for line in text.splitlines()
                                     if line.strip() and not line.startswith("#")]
        return self._cache[function]

    def _run(self, function: str, executor: str | None, arguments: dict) -> None:
        for line in self._lines(function):
            if line.startswith("$"):
                line = _MACRO_VARIABLE.sub(lambda m: str(arguments[m.group(1)]), line[1:])
            if self._command(line, executor):
                return

    # ------------------------------------------------------------------ commands
    def _command(self, line: str, executor: str | None) -> bool:
        """Run one command; True when it ended the function (`return`)."""
        self.commands += 1
        words = line.split()
        head = words[0]
        if head == "return":
            if words[1] == "run":
                self._command(line.split(" ", 2)[2], executor)
            return True
        if head == "function":
            raw = line.split(" ", 2)[2] if len(words) > 2 else ""
            arguments = {k: (quoted if quoted else v) for k, v, quoted in _MACRO_ARGUMENT.findall(raw)}
            self._run(words[1], executor, arguments)
        elif head == "execute":
            return self._execute(words[1:], executor)
        elif head == "tag":
            for entity in self._select(words[1], executor):
                (entity.tags.add if words[2] == "add" else entity.tags.discard)(words[3])
        elif head == "tellraw":
            self.messages.append(line)
        elif head == "kill":
            doomed = {id(e) for e in self._select(words[1], executor)}
            self.entities = [e for e in self.entities if id(e) not in doomed]
        elif head == "scoreboard":
            self._scoreboard(words[1:], executor)
        elif not (head == "data" and words[1] == "merge"):
            raise AssertionError(f"unsupported: {line}")
        return False

    def _scoreboard(self, words: list[str], executor: str | None) -> None:
        if words[0] == "objectives" or words[1] in ("enable", "get"):
            return
        action, target, objective, *rest = words[1:]
        for holder in self._holders(target, executor):
            key = (holder, objective)
            if action == "set":
                self.scores[key] = int(rest[0])
            elif action in ("add", "remove"):
                delta = int(rest[0]) if action == "add" else -int(rest[0])
                self._store(key, self.scores.get(key, 0) + delta)
            elif action == "operation":
                op, source, source_objective = rest
                (source,) = self._holders(source, executor)
                a, b = self.scores.get(key, 0), self.scores.get((source, source_objective), 0)
                if op == "><":
                    self.scores[key], self.scores[source, source_objective] = b, a
                else:
                    self._store(key, _OPS[op](a, b))
            else:
                raise AssertionError(f"unsupported: scoreboard {words}")

    def _store(self, key: tuple[str, str], value: int) -> None:
        if wrap32(value) != value:
            raise Overflow(f"{key} = {value} wraps")
        self.scores[key] = value

    def _execute(self, words: list[str], executor: str | None) -> bool:
        while words[0] != "run":
            if words[0] == "as":
                ended = False
                for entity in self._select(words[1], executor):
                    ended |= self._execute(words[2:], entity.name)
                return ended
            if words[:3] == ["store", "result", "score"]:
                (holder,) = self._holders(words[3], executor)
                get = words[words.index("run") + 1:]
                assert get[:3] == ["data", "get", "entity"] and get[4].startswith("Rotation["), get
                (entity,) = self._select(get[3], executor)
                self.commands += 1
                value = entity.rotation[int(get[4][len("Rotation["):-1])] * float(get[5])
                self.scores[holder, words[4]] = math.floor(value)
                return False
            if words[0] == "store":
                (entity,) = self._select(words[3], executor)
                axis = int(words[4][len("Pos["):-1])
                *_, holder, objective = words[words.index("run") + 1:]
                (holder,) = self._holders(holder, executor)
                self.commands += 1
                entity.pos[axis] = self.scores[holder, objective] * float(words[6])
                return False
            mode, kind = words[0], words[1]
            if kind == "entity":
                passed = bool(self._select(words[2], executor))
                words = words[3:]
            else:
                (holder,) = self._holders(words[2], executor)
                value = self.scores.get((holder, words[3]))
                if words[4] == "matches":
                    passed = _in_range(value, words[5])
                    words = words[6:]
                else:
                    (other,) = self._holders(words[5], executor)
                    other_value = self.scores.get((other, words[6]))
                    passed = value is not None and other_value is not None and _CMP[words[4]](
                        value, other_value)
                    words = words[7:]
            if passed != (mode == "if"):
                return False
        return self._command(" ".join(words[1:]), executor)

    # ------------------------------------------------------------------ selectors
    def _holders(self, target: str, executor: str | None) -> list[str]:
        if target.startswith("@"):
            return [e.name for e in self._select(target, executor)]
        return [target]

    def _select(self, selector: str, executor: str | None) -> list:
        if selector.startswith("@s"):
            assert executor is not None, "@s used without an executor"
            chosen = [e for e in self.entities if e.name == executor] or [Entity(executor)]
        elif selector.startswith("@a"):
            chosen = [e for e in self.entities if e.player]
        else:
            assert selector.startswith("@e"), selector
            chosen = [e for e in self.entities if not e.player]
        limit = None
        for key, value in re.findall(r"(\w+)=(\{[^}]*\}|[^,\]]+)", selector):
            if key == "tag":
                wanted = value.lstrip("!")
                chosen = [e for e in chosen if (wanted in e.tags) != value.startswith("!")]
            elif key == "scores":
                for objective, text in re.findall(r"([\w.]+)=([-\d.]+)", value):
                    chosen = [e for e in chosen if _in_range(self.scores.get((e.name, objective)), text)]
            elif key == "limit":
                limit = int(value)
            elif key == "type":
                chosen = []  # only markers are typed in the pack, and they are not modelled
        return chosen[:limit]


def _emulator_runner():
    try:
        from emulator import Emulator
    except ImportError:
        return None

    class EmulatorRunner:
        """`emulator.Emulator` with its overflow sanitizer on."""

        name = "emulator"

        def __init__(self) -> None:
            self._emu = Emulator(sanitize=True)
            self._emu.load(str(PACK))
            self.set_score = self._emu.set_score
            self.score = self._emu.score
            self.call("pool:load")

        def call(self, function: str) -> None:
            self._emu.call(function)
            if self._emu.overflows:
                raise Overflow(str(self._emu.overflows))
            assert not self._emu.diagnostics, self._emu.diagnostics

    return EmulatorRunner


RUNNERS = [r for r in (MiniScoreboard, _emulator_runner()) if r is not None]
