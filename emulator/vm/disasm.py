"""The VM's bytecode as text: a function's instructions (``pc OP operands``) beside its source
lines, what ``dpemu disasm`` prints. Names and operand kinds come from the opcode table
(:mod:`emulator.vm.opcodes`)."""
from __future__ import annotations

from emulator.vm import loop as vm
from emulator.vm import opcodes
from emulator.vm.program import Program
from emulator.world.state import Scoreboard

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
        if value == vm.HOLDER_TRACKED:
            return "*"
        return "@s" if value == vm.HOLDER_SELF else scoreboard.holders[value]
    if kind == "s":
        return {vm.SEL_TRACKED: "*", vm.REL_VEHICLE: "vehicle", vm.REL_PASSENGERS: "passengers"}.get(value, f"sel#{value}")
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
        return program.levels.names[value]
    if kind == "p":
        return f"->{value}"
    if kind == "x":
        return f"[{type(program.host_ops[value].node).__name__}]"
    if kind == "m":
        return program.macro_calls[value].function
    if kind == "_":
        return ""
    return str(value)
