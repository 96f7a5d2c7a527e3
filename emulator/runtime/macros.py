"""Function instantiation with macro arguments (MacroFunction, 1.20.2+).

A function without ``$`` lines ignores arguments. A macro function needs arguments holding every
key its lines use (checked before any line runs); each ``$`` line is substituted and parsed with
``parse_command``; instances are cached per argument values.
"""
from __future__ import annotations

import math
from decimal import ROUND_HALF_EVEN, Context, Decimal

from emulator.world.nbt_ops import snbt
from emulator.world.semantics import double_to_float
from mcfunction_parser import ast, nbt
from mcfunction_parser.parse import parse_command

from emulator.world.errors import CommandFailure
from emulator.world.errors import MESSAGES


def stringify(value) -> str:
    """MacroFunction.stringify: floats with up to 15 decimals and no exponent, integers plain,
    strings raw, compounds and lists as SNBT."""
    if isinstance(value, float):
        # a float tag is widened from its float32 value ((double) floatTag.getAsFloat())
        number = double_to_float(value) if isinstance(value, nbt.Float) else float(value)
        if not math.isfinite(number):
            return "NaN" if number != number else ("-\u221e" if number < 0 else "\u221e")  # DecimalFormatSymbols
        exact = Decimal(repr(number))
        text = format(exact.quantize(Decimal("1e-15"), ROUND_HALF_EVEN, Context(prec=400)), "f")
        return text.rstrip("0").rstrip(".") if "." in text else text
    if isinstance(value, bool):
        return "1" if value else "0"
    if isinstance(value, int):
        return str(int(value))
    if isinstance(value, str):
        return str(value)
    return snbt(value)


def parameters(function: ast.Function) -> list[str]:
    """Every key the function's macro lines use, in order of first use."""
    seen: dict[str, None] = {}
    for command in function.commands:
        if isinstance(command, ast.MacroLine):
            for key in command.keys:
                seen.setdefault(key)
    return list(seen)


class MacroExpander:
    def __init__(self, version: tuple[int, int, int]) -> None:
        self.version = version
        self._cache: dict[tuple, tuple[ast.Command, ...]] = {}

    def instantiate(self, function: ast.Function, arguments) -> tuple[ast.Command, ...]:
        if not function.is_macro:
            return function.commands
        if arguments is None:
            raise _failure(function, MESSAGES["commands.function.error.missing_arguments"].format(function.id))
        keys = parameters(function)
        values = []
        for key in keys:
            if key not in arguments:
                raise _failure(function, MESSAGES["commands.function.error.missing_argument"].format(function.id, key))
            values.append(stringify(arguments[key]))
        cache_key = (function.id, tuple(values))
        commands = self._cache.get(cache_key)
        if commands is None:
            substitutions = dict(zip(keys, values))
            commands = tuple(self._expand(function, c, substitutions) for c in function.commands)
            self._cache[cache_key] = commands
        return commands

    def _expand(self, function: ast.Function, command: ast.Command, substitutions: dict[str, str]) -> ast.Command:
        if not isinstance(command, ast.MacroLine):
            return command
        text = command.template
        for key, value in substitutions.items():
            text = text.replace(f"$({key})", value)
        parsed, diagnostics = parse_command(text, command.loc, self.version)
        errors = [d for d in diagnostics if d.severity == "error"]
        if parsed is None or errors:
            reason = errors[0].message if errors else "not a command"
            raise _failure(function, MESSAGES["commands.function.error.parse"].format(function.id, text, reason))
        return parsed


def _failure(function: ast.Function, reason: str) -> CommandFailure:
    """FunctionCommand.ERROR_FUNCTION_INSTANTATION_FAILURE (reported: a pack mistake)."""
    return CommandFailure("commands.function.instantiationFailure", function.id, reason, report=True)
