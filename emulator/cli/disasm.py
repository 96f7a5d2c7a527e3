"""``dpemu disasm PACK FUNCTION``: the bytecode of a function beside its source lines
(:mod:`emulator.vm.disasm`; the VM is imported when the command runs, not for ``dpemu --help``)."""
from __future__ import annotations

import click

from emulator.cli.params import PackPath
from emulator.world.state import WorldState


def _why_missing(packs, function_id: str) -> str:
    """The load error of the function's own file, when it failed to load (the game drops a function
    with a line it cannot parse)."""
    namespace, path = function_id.split(":", 1)
    for diag in packs.errors:
        where = diag.path.replace("\\", "/")
        if f"/{namespace}/" in where and where.endswith(f"/{path}.mcfunction"):
            return f": it failed to load:\n{diag.format()}"
    return ""


@click.command("disasm")
@click.argument("pack", type=PackPath())
@click.argument("function")
@click.option("--mc", "mc_version", metavar="VERSION", help="Game version (default: the pack's).")
def disasm(pack: str, function: str, mc_version: str | None) -> None:
    """Print FUNCTION's bytecode beside its source lines."""
    from emulator.vm.backend import NumbaBackend
    from emulator.vm.disasm import disassemble
    from mcfunction_parser.pack.loader import load_packs

    packs = load_packs([pack], mc_version)
    function_id = function if ":" in function else f"minecraft:{function}"
    if function_id not in packs.functions:
        raise click.BadParameter(f"no function {function_id} in {pack}{_why_missing(packs, function_id)}",
                                 param_hint="FUNCTION")
    if packs.functions[function_id].is_macro:
        raise click.BadParameter(f"{function_id} is a macro function: it is compiled per argument set at run time",
                                 param_hint="FUNCTION")
    state = WorldState()
    backend = NumbaBackend()
    backend.load(packs, state)
    program = backend.program
    for line in disassemble(program, state.scoreboard, program.function_index[function_id], packs.sources):
        click.echo(line)
