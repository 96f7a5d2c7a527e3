"""The numba backend: the opcode table, the bytecode compiler, the jitted dispatch loop, the
entity arrays it reads, and the host bridge that runs the rest through :mod:`emulator.commands`."""
