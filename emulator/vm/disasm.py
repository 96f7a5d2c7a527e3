"""The VM's bytecode as text: a function's instructions (``pc OP operands``) beside its source
lines, what ``dpemu disasm`` prints."""
from __future__ import annotations

from emulator.vm import loop as vm
from emulator.vm.program import Program
from emulator.world.state import Scoreboard

# operand kinds per opcode, in slot order: h holder, o objective, i int, p pc, f function,
# c comparison, n name, x host op, m macro call, b flag, s selector, d float
_OPERANDS_OPERATION = "hoho"
_OPERANDS = {
    vm.OP_CMD: "p", vm.OP_STAGESDONE: "p", vm.OP_SET: "hoi", vm.OP_ADD: "hoi", vm.OP_REMOVE: "hoi",
    vm.OP_RESET: "ho", vm.OP_RESETALL: "h", vm.OP_GET: "ho",
    vm.OP_IFSCORE: "choho" + "bb", vm.OP_IFMATCH: "hoii_bb", vm.OP_CHKOBJ: "obb", vm.OP_STORE: "bho",
    vm.OP_CALL: "f", vm.OP_RETV: "ib", vm.OP_RETFAIL: "_b", vm.OP_IFFN_STEP: "p", vm.OP_RETIFHAS: "p", vm.OP_IFNOFN: "p", vm.OP_IFFN_END: "b", vm.OP_FAIL: "inbb",
    vm.OP_RESULT: "bi", vm.OP_JMPDEAD: "p", vm.OP_HOST: "x", vm.OP_HOSTSTAGE: "xb", vm.OP_HOSTSTORE: "x",
    vm.OP_MACRO: "m", vm.OP_TAG: "sib", vm.OP_IFENT: "s_____b", vm.OP_ENABLE: "ho", vm.OP_SELHOLDERS: "sb", vm.OP_ASSTAGE: "sbb", vm.OP_TP: "sdi",
    vm.OP_POSSTAGE: "_b", vm.OP_STOREPOS: "ibd", vm.OP_GETPOS: "i", vm.OP_LOG: "xs",
}
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
    op = row[0]
    parts = [vm.OP_NAMES.get(op, str(op))]
    kinds = _OPERANDS_OPERATION if op >= vm.OP_OPER_BASE else _OPERANDS.get(op, "")
    for kind, value in zip(kinds, row[1:]):
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
    if kind == "p":
        return f"->{value}"
    if kind == "x":
        return f"[{type(program.host_ops[value].node).__name__}]"
    if kind == "m":
        return program.macro_calls[value].function
    if kind == "_":
        return ""
    return str(value)
