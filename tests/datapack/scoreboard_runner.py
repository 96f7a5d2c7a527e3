"""Runners that execute pool datapack functions on fake players, for the math tests.

`MiniScoreboard` interprets only the command subset the math library uses (scoreboard
players set/add/remove/operation, `execute if|unless score ... run`, `function`, `return [run]`)
with the Java semantics of `emulator.semantics`. It is the stepping stone used until
`emulator.Emulator` runs the pack; tests run on every runner available.
"""
from __future__ import annotations

import re

from emulator.semantics import floor_div, floor_mod, wrap32

from pack_paths import PACK

_OPS = {
    "+=": lambda a, b: wrap32(a + b),
    "-=": lambda a, b: wrap32(a - b),
    "*=": lambda a, b: wrap32(a * b),
    "/=": floor_div,
    "%=": floor_mod,
    "=": lambda a, b: b,
    "<": min,
    ">": max,
}
_CMP = {"<": int.__lt__, "<=": int.__le__, "=": int.__eq__, ">=": int.__ge__, ">": int.__gt__}


class Overflow(AssertionError):
    """An operation wrapped: the math library promises it never does."""


class MiniScoreboard:
    name = "mini"

    def __init__(self) -> None:
        self.scores: dict[tuple[str, str], int] = {}
        self.commands = 0
        self._executor: str | None = None
        self._cache: dict[str, list[str]] = {}
        self.call("pool:load")

    def set_score(self, holder: str, objective: str, value: int) -> None:
        self.scores[holder, objective] = value

    def score(self, holder: str, objective: str) -> int:
        return self.scores[holder, objective]

    def call(self, function: str, as_: str | None = None) -> None:
        """Run ``function``; ``as_`` names the fake player that ``@s`` stands for."""
        self._executor = as_
        self._run(function)

    def _lines(self, function: str) -> list[str]:
        if function not in self._cache:
            namespace, path = function.split(":")
            text = (PACK / "data" / namespace / "function" / f"{path}.mcfunction").read_text()
            self._cache[function] = [
                line for line in text.splitlines() if line.strip() and not line.startswith("#")
            ]
        return self._cache[function]

    def _run(self, function: str) -> None:
        for line in self._lines(function):
            if self._command(line.split()):
                return

    def _command(self, words: list[str]) -> bool:
        """Run one command; True when it was `return` (ends the function)."""
        self.commands += 1
        if words[:2] == ["scoreboard", "objectives"]:
            return False
        if words[0] == "return":
            if words[1] == "run":
                self._command(words[2:])
            return True
        if words[0] == "function":
            self._run(words[1])
            return False
        if words[0] == "execute":
            return self._execute(words[1:])
        assert words[:2] == ["scoreboard", "players"], words
        action, holder, objective, *rest = words[2:]
        key = (self._holder(holder), objective)
        if action == "set":
            self.scores[key] = int(rest[0])
        elif action in ("add", "remove"):
            delta = int(rest[0]) if action == "add" else -int(rest[0])
            self._store(key, self.scores.get(key, 0) + delta)
        elif action == "operation":
            op, source, source_objective = rest
            source = self._holder(source)
            a = self.scores.get(key, 0)
            b = self.scores.get((source, source_objective), 0)
            if op == "><":
                self.scores[key], self.scores[source, source_objective] = b, a
            else:
                raw = {"+=": a + b, "-=": a - b, "*=": a * b}.get(op)
                self._store(key, raw if raw is not None else _OPS[op](a, b))
        else:
            raise AssertionError(f"unsupported: {words}")
        return False

    def _holder(self, name: str) -> str:
        if name == "@s":
            assert self._executor is not None, "@s used without an executor"
            return self._executor
        return name

    def _store(self, key: tuple[str, str], value: int) -> None:
        if wrap32(value) != value:
            raise Overflow(f"{key} = {value} wraps")
        self.scores[key] = value

    def _execute(self, words: list[str]) -> bool:
        while words[0] != "run":
            mode, kind, holder, objective = words[:4]
            assert kind == "score", words
            value = self.scores.get((self._holder(holder), objective))
            if words[4] == "matches":
                low, _, high = words[5].partition("..")
                if ".." not in words[5]:
                    high = low
                passed = value is not None and (not low or value >= int(low)) and (
                    not high or value <= int(high))
                words = words[6:]
            else:
                other = self.scores.get((self._holder(words[5]), words[6]))
                passed = value is not None and other is not None and _CMP[words[4]](value, other)
                words = words[7:]
            if passed != (mode == "if"):
                return False
        return self._command(words[1:])


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
