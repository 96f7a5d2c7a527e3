"""Test environments (1.21.5+, PackTest 2's ``@environment``): ``data/<ns>/test_environment/<path>.json``
and the built-in ``minecraft:default`` (TestEnvironmentDefinition and its types, minecraft.wiki "Test
environment definition").

- ``all_of`` {definitions: [id or definition...]}: each in order;
- ``function`` {setup?, teardown?}: functions run as the server before and after the test;
- ``game_rules`` {bool_rules: [{rule, value}], int_rules: [{rule, value}]} (and the newer
  ``rules`` map): set for the test;
- ``time_of_day`` {time}: the day time for the test.
The runner sets a batch's environment up before its tests and tears it down when the next batch
starts: the teardown functions run and the rules and day time go back to what they were
(TestEnvironmentDefinition.SetGameRules, ClockTime teardown). A type the emulator
does not model (``weather``: there is no weather here; any other) makes the test inconclusive
with that reason, never silently ignored.
"""
from __future__ import annotations

from dataclasses import dataclass, field

BUILTIN = {"minecraft:default": {"type": "minecraft:all_of", "definitions": []}}


class EnvironmentError(Exception):
    """The environment cannot be set up: unknown, malformed, or not modelled (``unmodelled``)."""

    def __init__(self, message: str, unmodelled: bool = False) -> None:
        super().__init__(message)
        self.message, self.unmodelled = message, unmodelled


@dataclass
class Environment:
    setup: list[str] = field(default_factory=list)
    teardown: list[str] = field(default_factory=list)
    rules: list[tuple[str, str]] = field(default_factory=list)  # (game rule, value as the command writes it)
    day_time: int | None = None


def resolve(packs, environment_id: str) -> Environment:
    """What ``environment_id`` does, from the packs' files and the built-in environments."""
    found = Environment()
    _apply(packs, _definition(packs, environment_id), found, [environment_id])
    return found


def _definition(packs, environment_id: str) -> dict:
    if environment_id in BUILTIN:
        return BUILTIN[environment_id]
    definition = packs.test_environments.get(environment_id)
    if definition is None:  # no such file, or one the game refuses (its error was reported at load)
        namespace, _, path = environment_id.partition(":")
        raise EnvironmentError(f"Unknown test environment {environment_id} (no data/{namespace}/test_environment/"
                               f"{path}.json that loads)")
    return definition


def _apply(packs, definition: dict, into: Environment, trail: list[str]) -> None:
    kind = str(definition.get("type", "")).removeprefix("minecraft:")
    where = trail[-1]
    if kind == "all_of":
        for member in definition.get("definitions", []):
            if isinstance(member, str):
                member_id = member if ":" in member else "minecraft:" + member
                if member_id in trail:
                    raise EnvironmentError(f"test environment {where}: {member_id} includes itself")
                _apply(packs, _definition(packs, member_id), into, trail + [member_id])
            elif isinstance(member, dict):
                _apply(packs, member, into, trail)
            else:
                raise EnvironmentError(f"test environment {where}: a definition must be an id or an object")
    elif kind == "function":
        for key, functions in (("setup", into.setup), ("teardown", into.teardown)):
            if key in definition:
                name = str(definition[key])
                functions.append(name if ":" in name else "minecraft:" + name)
    elif kind == "game_rules":
        for entry in [*definition.get("bool_rules", []), *definition.get("int_rules", [])]:
            into.rules.append((str(entry["rule"]), _rule_text(entry["value"])))
        for rule, value in definition.get("rules", {}).items():
            into.rules.append((rule.removeprefix("minecraft:"), _rule_text(value)))
    elif kind == "time_of_day":
        into.day_time = int(definition["time"])
    elif kind == "weather":
        raise EnvironmentError(f"test environment {where}: weather is not emulated", unmodelled=True)
    else:
        raise EnvironmentError(f"test environment {where}: type {definition.get('type')!r} is not emulated",
                               unmodelled=True)


def _rule_text(value) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    return str(value)
