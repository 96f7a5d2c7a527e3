"""``dpemu disasm PACK FUNCTION``: the bytecode of a function beside its source lines."""
from __future__ import annotations

import click

from emulator.vm import loop as vm
from emulator.vm import opcodes
from emulator.vm.backend import NumbaBackend
from emulator.vm.program import Program
from emulator.world.state import Scoreboard, WorldState

_COMPARISON_NAMES = {v: k for k, v in vm.CMP_BY_SYMBOL.items()}


def disassemble(program: Program, scoreboard: Scoreboard, function_index: int, sources: dict[str, list[str]]) -> list[str]:
    """Lines of text: each source line once, then its instructions ``pc OP operands``."""
    out: list[str] = []
    start = program.starts[function_index]
    pc = start
    shown = None
    while pc < len(program.rows) and program.owner[pc] == function_index:
        loc = program.locs[pc]
        if loc is not None and (loc.path, loc.line) != shown:
            shown = (loc.path, loc.line)
            lines = sources.get(loc.path, [])
            text = lines[loc.line - 1].rstrip("\n") if 0 < loc.line <= len(lines) else ""
            out.append(f"{loc.line:>5} | {text}")
        out.append(f"      |   {pc:>6}  {_instruction(program, scoreboard, pc)}")
        pc += 1
        if program.rows[pc - 1][0] == vm.OP_FEND:
            break
    return out


def _instruction(program: Program, scoreboard: Scoreboard, pc: int) -> str:
    row = program.rows[pc]
    op = opcodes.BY_CODE[row[0]]
    parts = [op.name]
    for kind, value in zip(op.operands, row[1:]):
        parts.append(_operand(program, scoreboard, kind, value))
    return " ".join(p for p in parts if p)


def _operand(program: Program, scoreboard: Scoreboard, kind: str, value: int) -> str:
    if kind == "h":
        if value == vm.HOLDER_SELBUF:
            return "<selected>"
        return "@s" if value == vm.HOLDER_SELF else scoreboard.holders[value]
    if kind == "s":
        return f"sel#{value}"
    if kind == "d":
        return repr(program.floats[value])
    if kind == "o":
        return scoreboard.objectives[value]
    if kind == "f":
        return program.functions[value]
    if kind == "c":
        return _COMPARISON_NAMES[value]
    if kind == "n":
        return program.names[value]
    if kind == "l":
        return program.dimensions[value]
    if kind == "p":
        return f"->{value}"
    if kind == "x":
        return f"[{type(program.host_ops[value].node).__name__}]"
    if kind == "m":
        return program.macro_calls[value].function
    if kind == "_":
        return ""
    return str(value)


@click.command("disasm")
@click.argument("pack", type=click.Path(exists=True, file_okay=False))
@click.argument("function")
@click.option("--mc", "mc_version", metavar="VERSION", help="Game version (default: the pack's).")
def disasm(pack: str, function: str, mc_version: str | None) -> None:
    """Print FUNCTION's bytecode beside its source lines."""
    from mcfunction_parser.pack.loader import load_packs

    packs = load_packs([pack], mc_version)
    function_id = function if ":" in function else f"minecraft:{function}"
    if function_id not in packs.functions:
        raise click.BadParameter(f"no function {function_id} in {pack}", param_hint="FUNCTION")
    if packs.functions[function_id].is_macro:
        raise click.BadParameter(f"{function_id} is a macro function: it is compiled per argument set at run time",
                                 param_hint="FUNCTION")
    state = WorldState()
    backend = NumbaBackend()
    backend.load(packs, state)
    program = backend.program
    for line in disassemble(program, state.scoreboard, program.function_index[function_id], packs.sources):
        click.echo(line)
