"""Test environment JSON (``data/<ns>/test_environment/<path>.json``, 1.21.5+) as the game loads it:
TestEnvironmentDefinition.DIRECT_CODEC dispatches on ``type``; a file whose type is unknown or
whose fields do not decode is refused ("Couldn't parse element ...") and does not exist.

Types (decompiled 1.21.5 - 1.21.11 and 26.1, gametest/framework/TestEnvironmentDefinition.bootstrap;
minecraft.wiki "Test environment definition"): ``all_of`` {definitions: list of ids or
definitions}, ``function`` {setup?, teardown?: function ids}, ``game_rules`` ({bool_rules,
int_rules}: lists of {rule, value} before 1.21.11, {rules}: a map from it), ``weather`` {weather:
clear, rain or thunder}; ``time_of_day`` {time: int >= 0} until 26.1, which replaced it with
``clock_time`` {clock: a world clock id, time: int >= 0}. A type a release after the newest known
may add is a warning.
"""
from __future__ import annotations

from typing import Any

from mcfunction_parser.diagnostics import ERROR, WARNING, Diagnostic
from mcfunction_parser.pack.text import JsonDocument

Version = tuple[int, int, int]
SINCE: Version = (1, 21, 5)  # 25w02a: the test_environment registry
NEWEST_KNOWN: Version = (26, 1, 0)
CLOCKS: Version = (26, 1, 0)  # clock_time replaced time_of_day (the world clocks)


def types(version: Version) -> tuple[str, ...]:
    """The definition types the release registers."""
    return ("all_of", "function", "game_rules", "clock_time" if version >= CLOCKS else "time_of_day", "weather")


def problem(value: Any, version: Version) -> tuple[str, str, str] | None:
    """(severity, message, the JSON string to point at) when the game refuses the definition."""
    if isinstance(value, str):
        return None  # an id inside all_of
    if not isinstance(value, dict):
        return ERROR, "a test environment must be a JSON object (or an id inside all_of)", ""
    raw = value.get("type")
    kind = raw.removeprefix("minecraft:") if isinstance(raw, str) else None
    if kind is None:
        return ERROR, 'a test environment needs "type"', ""
    if kind not in types(version):
        severity = WARNING if version > NEWEST_KNOWN else ERROR
        return severity, f"unknown test environment type '{raw}'", raw
    if kind == "all_of":
        members = value.get("definitions")
        if not isinstance(members, list):
            return ERROR, 'all_of needs "definitions": a list of ids or definitions', raw
        return next(filter(None, (problem(m, version) for m in members)), None)
    if kind == "function" and any(not isinstance(value.get(k, ""), str) for k in ("setup", "teardown")):
        return ERROR, '"setup" and "teardown" are function ids', raw
    if kind == "time_of_day" and not (isinstance(value.get("time"), int) and value["time"] >= 0):
        return ERROR, 'time_of_day needs "time": an int of at least 0', raw
    if kind == "clock_time" and not (isinstance(value.get("clock"), str)
                                     and isinstance(value.get("time"), int) and value["time"] >= 0):
        return ERROR, 'clock_time needs "clock": a world clock id and "time": an int of at least 0', raw
    if kind == "weather" and value.get("weather") not in ("clear", "rain", "thunder"):
        return ERROR, 'weather needs "weather": clear, rain or thunder', raw
    if kind == "game_rules":
        key = "rules" if version >= (1, 21, 11) else "bool_rules"
        if version >= (1, 21, 11) and not isinstance(value.get("rules", {}), dict):
            return ERROR, '"rules" must be a map of game rules', raw
        if version < (1, 21, 11) and any(not isinstance(value.get(k, []), list) for k in ("bool_rules", "int_rules")):
            return ERROR, f'"{key}" and "int_rules" must be lists of {{rule, value}}', raw
    return None


def validate(doc: JsonDocument, version: Version, what: str, diagnostics: list[Diagnostic]) -> bool:
    """Check one file; False (with an error) when the game refuses it."""
    found = problem(doc.value, version)
    if found is None:
        return True
    severity, message, token = found
    offset = doc.find_string(token) if token else -1
    diagnostics.append(doc.diagnostic(severity, f"{what} fails to load: {message}" if severity == ERROR
                                      else f"{what}: {message}", offset))
    return severity != ERROR
