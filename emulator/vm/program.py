"""A compiled program: bytecode, source map, function table, and the side tables the VM refers to.

The compiler appends to a :class:`Program` (macro instances are appended while a run is going on)
and :meth:`Program.arrays` hands the VM contiguous numpy arrays, rebuilt only after a change.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from emulator.vm.loop import OP_CALLREG, OP_HALT, OP_HOST, OP_RESUME, WIDTH
from emulator.vm.opcodes import BY_CODE
from emulator.world.dimensions import Levels
from mcfunction_parser.ast import Command, Subcommand
from mcfunction_parser.diagnostics import Loc


@dataclass(frozen=True, slots=True)
class HostOp:
    """A node the VM hands to :mod:`emulator.vm.host`: a final command, an execute stage or a store
    (which one is told by the opcode naming it). The VM charges the costs."""

    node: Command | Subcommand
    function: str


@dataclass(frozen=True, slots=True)
class MacroCall:
    """``function f {args}`` / ``function f with ...`` (or a plain call of a macro function)."""

    command: Command  # the FunctionCall
    function: str  # the macro function's id
    caller: str


@dataclass
class Program:
    rows: list[list[int]] = field(default_factory=list)
    locs: list[Loc | None] = field(default_factory=list)  # per instruction: its command's source
    owner: list[int] = field(default_factory=list)  # per instruction: function index (-1: stub)
    functions: list[str] = field(default_factory=list)  # function index -> id (macro instances too)
    function_index: dict[str, int] = field(default_factory=dict)
    starts: list[int] = field(default_factory=list)  # function index -> first pc (-1 until compiled)
    host_ops: list[HostOp] = field(default_factory=list)
    macro_calls: list[MacroCall] = field(default_factory=list)
    names: list[str] = field(default_factory=list)  # operands of OP_FAIL (missing function ids)
    floats: list[float] = field(default_factory=list)  # float operands (store scales), by index
    levels: Levels = field(default_factory=Levels)  # the world's: OP_IFDIM's operands and the contexts' CI_DIM
    opcodes: set[int] = field(default_factory=set)  # the opcodes the code uses (emulator.vm.variants)
    _arrays: tuple | None = None

    ROOT_PC = 0  # the root stub: CALLREG then HALT
    REWARD_PC = 2  # the reward stub: CALLREG then RESUME (an advancement reward run after a host command)

    def __post_init__(self) -> None:
        if not self.rows:
            for op in (OP_CALLREG, OP_HALT, OP_CALLREG, OP_RESUME):
                self.emit(op, loc=None, owner=-1)

    # ------------------------------------------------------------------ building
    def emit(self, op: int, *args: int, loc: Loc | None, owner: int) -> int:
        row = [op, *args] + [0] * (WIDTH - 1 - len(args))
        self.rows.append(row)
        self.opcodes.add(op)
        self.locs.append(loc)
        self.owner.append(owner)
        self._arrays = None
        return len(self.rows) - 1

    def to_host(self, codes: set[int]) -> None:
        """Each instruction with an opcode of ``codes`` becomes a HOST of its own host op (its ``x``
        operand): Python runs the command instead (emulator.vm.variants.TO_HOST)."""
        if not codes:
            return
        for row in self.rows:
            if row[0] in codes:
                row[:] = [OP_HOST, row[BY_CODE[row[0]].operands.index("x") + 1]] + [0] * (WIDTH - 2)
        self.opcodes -= codes
        self.opcodes.add(OP_HOST)
        self._arrays = None

    def patch(self, pc: int, slot: int, value: int) -> None:
        self.rows[pc][slot] = value
        self._arrays = None

    @property
    def next_pc(self) -> int:
        return len(self.rows)

    def intern_function(self, function_id: str) -> int:
        idx = self.function_index.get(function_id)
        if idx is None:
            idx = len(self.functions)
            self.functions.append(function_id)
            self.function_index[function_id] = idx
            self.starts.append(-1)
            self._arrays = None
        return idx

    def set_start(self, function_index: int, pc: int) -> None:
        self.starts[function_index] = pc
        self._arrays = None

    def intern_name(self, name: str) -> int:
        self.names.append(name)
        return len(self.names) - 1

    @property
    def next_float(self) -> int:
        return len(self.floats)

    def intern_float(self, value: float) -> int:
        self.floats.append(float(value))
        self._arrays = None
        return len(self.floats) - 1

    # ------------------------------------------------------------------ for the VM
    def arrays(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(code int32[n, WIDTH], func_start int64[functions], floats float64[k])``."""
        if self._arrays is None:
            code = np.array(self.rows, dtype=np.int32).reshape(-1, WIDTH)
            starts = np.array(self.starts, dtype=np.int64)
            floats = np.array(self.floats or [0.0], dtype=np.float64)
            self._arrays = (code, starts, floats)
        return self._arrays

    def function_of(self, pc: int) -> str:
        idx = self.owner[pc]
        return self.functions[idx] if idx >= 0 else "<root>"
