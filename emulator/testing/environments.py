"""Test environments (1.21.5+, PackTest 2's ``@environment``): ``data/<ns>/test_environment/<path>.json``
and the built-in ``minecraft:default``, set up before a batch's tests and torn down when the next
batch starts (GameTestRunner.runBatch, endCurrentEnvironment).

- ``resolve(packs, id)``: the definitions the environment is made of, in order (``all_of`` opened:
  ids and inline definitions, nested);
- ``set_up(emu, definitions)``: each definition's setup, in order; returns the activation (what
  each setup saved) that ``tear_down(emu, activation)`` takes.

What each does (decompiled TestEnvironmentDefinition, 1.21.5 - 1.21.11 and 26.1; minecraft.wiki
"Test environment definition"):
- ``function`` {setup?, teardown?}: the function runs as the server; one that does not exist is
  the game's logged error ("Test Batch failed for non-existent function"), and the tests still run;
- ``game_rules``: the rules set; torn down to each rule's default before 26.1, to the value it had
  before the setup from 26.1 (SetGameRules: ``createRule()``; 26.1's saved GameRuleMap);
- ``time_of_day`` {time} (until 26.1): the day time set, never set back; ``clock_time`` {clock,
  time} (26.1+): the clock's ticks set, and set back to what they were;
- ``weather`` {clear|rain|thunder}: ServerLevel.setWeatherParameters(100000, 0, false, false) /
  (0, 100000, true, false) / (0, 100000, true, true) (Weather.Type); torn down by
  resetWeatherCycle (no rain or thunder, their timers 0), then from 26.1 the weather it found
  (thundering, raining or clear, as Level.isThundering/isRaining read it) applied again. The rain
  and thunder levels then move 0.01 a tick, so ``weather_check`` sees rain after about 20 ticks,
  as in the game;
- ``all_of``: its definitions set up in order; torn down in that order before 26.1, in reverse
  from 26.1 (AllOf.teardown: ``activations.reversed()``).
An environment that does not exist fails the tests using it.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from mcfunction_parser.pack.test_environments import CLOCKS
from emulator.world.state import GAMERULE_DEFAULTS, Gamerules

BUILTIN = {"minecraft:default": {"type": "minecraft:all_of", "definitions": []}}
SAVED_DATA = CLOCKS  # 26.1: TestEnvironmentDefinition<SavedDataType>, each teardown given what its setup saved
OVERWORLD = "minecraft:overworld"
# Weather.Type: clear time, rain (and thunder) time, raining, thundering
WEATHER = {"clear": (100000, 0, False, False), "rain": (0, 100000, True, False), "thunder": (0, 100000, True, True)}


class EnvironmentError(Exception):
    """The environment cannot be set up: unknown, malformed, or of a type not modelled (``unmodelled``:
    one a release newer than the newest known may add)."""

    def __init__(self, message: str, unmodelled: bool = False) -> None:
        super().__init__(message)
        self.message, self.unmodelled = message, unmodelled


@dataclass
class Activation:
    """The definitions set up for a batch and what each setup saved for its teardown."""
    steps: list[tuple[dict, object]] = field(default_factory=list)


def resolve(packs, environment_id: str) -> list[dict]:
    """The definitions ``environment_id`` is made of, ``all_of`` opened, in order."""
    found: list[dict] = []
    _flatten(packs, _definition(packs, environment_id), found, [environment_id])
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


def _kind(definition: dict) -> str:
    return str(definition.get("type", "")).removeprefix("minecraft:")


def _flatten(packs, definition: dict, into: list[dict], trail: list[str]) -> None:
    kind = _kind(definition)
    if kind != "all_of":
        if kind not in _SETUP:
            raise EnvironmentError(f"test environment {trail[-1]}: type {definition.get('type')!r} is not emulated",
                                   unmodelled=True)
        into.append(definition)
        return
    for member in definition.get("definitions", []):
        if isinstance(member, dict):
            _flatten(packs, member, into, trail)
            continue
        member_id = str(member) if ":" in str(member) else "minecraft:" + str(member)
        if member_id in trail:
            raise EnvironmentError(f"test environment {trail[-1]}: {member_id} includes itself")
        _flatten(packs, _definition(packs, member_id), into, trail + [member_id])


def set_up(emu, definitions: list[dict]) -> Activation:
    activation = Activation()
    for definition in definitions:
        activation.steps.append((definition, _SETUP[_kind(definition)](emu, definition)))
    return activation


def tear_down(emu, activation: Activation) -> None:
    saved_data = emu.packs.version >= SAVED_DATA
    for definition, saved in (reversed(activation.steps) if saved_data else activation.steps):
        _TEARDOWN[_kind(definition)](emu, definition, saved, saved_data)


# ----------------------------------------------------------------------------- each type
def _run(emu, definition: dict, key: str) -> None:
    """Functions.run: the function as the server; a missing one is the game's logged error."""
    name = definition.get(key)
    if name is None:
        return
    function = name if ":" in name else "minecraft:" + name
    if function in emu.runtime.packs.functions:  # as a reload left them
        emu.call(function)
    else:
        emu.state.error(f"Test Batch failed for non-existent function {function}")


def _rules(definition: dict) -> list[tuple[str, str]]:
    """(rule, value as the gamerule command writes it): the lists before 1.21.11, the map from it."""
    entries = [(str(e["rule"]), e["value"]) for e in [*definition.get("bool_rules", []), *definition.get("int_rules", [])]]
    entries += [(rule.removeprefix("minecraft:"), value) for rule, value in definition.get("rules", {}).items()]
    return [(rule, ("true" if value else "false") if isinstance(value, bool) else str(value)) for rule, value in entries]


def _set_rules(emu, definition: dict) -> list[tuple[str, str | None]]:
    rules = emu.state.gamerules
    before = [(rule, rules.get(rule)) for rule, _ in _rules(definition)]
    for rule, value in _rules(definition):
        rules.set(rule, value)
    return before


def _reset_rules(emu, definition: dict, before, saved_data: bool) -> None:
    rules = emu.state.gamerules
    for rule, value in (reversed(before) if saved_data else before):
        value = value if saved_data else GAMERULE_DEFAULTS.get(Gamerules.canonical(rule))
        if value is not None:
            rules.set(rule, value)
        else:  # a rule the emulator knows no default of: as if never set
            rules.values.pop(Gamerules.canonical(rule), None)


def _set_time(emu, definition: dict) -> None:
    emu.state.daytime = int(definition["time"])


def _set_clock(emu, definition: dict) -> int:
    clocks, clock = emu.state.clocks, str(definition["clock"])
    clock = clock if ":" in clock else "minecraft:" + clock
    if clocks is None or clock not in clocks:
        raise EnvironmentError(f"test environment: unknown world clock {clock}")
    before = clocks.ticks(clock)
    clocks.set_ticks(clock, int(definition["time"]))
    return before


def _reset_clock(emu, definition: dict, before: int, saved_data: bool) -> None:
    clock = str(definition["clock"])
    emu.state.clocks.set_ticks(clock if ":" in clock else "minecraft:" + clock, before)


def _set_weather(emu, definition: dict) -> str:
    weather = emu.state.weather
    found = ("thunder" if weather.is_thundering(OVERWORLD) else "rain" if weather.is_raining(OVERWORLD)
             else "clear")
    weather.set(*WEATHER[definition["weather"]])
    return found


def _reset_weather(emu, definition: dict, found: str, saved_data: bool) -> None:
    weather = emu.state.weather
    weather.reset_cycle()
    if saved_data:
        weather.set(*WEATHER[found])


def _nothing(*_) -> None:
    return None


_SETUP = {"function": lambda emu, d: _run(emu, d, "setup"), "game_rules": _set_rules, "time_of_day": _set_time,
          "clock_time": _set_clock, "weather": _set_weather}
_TEARDOWN = {"function": lambda emu, d, _saved, _typed: _run(emu, d, "teardown"), "game_rules": _reset_rules,
             "time_of_day": _nothing, "clock_time": _reset_clock, "weather": _reset_weather}
