"""The ``dpemu`` command line: one module per subcommand in this package, loaded when used.

Other installed packages add subcommands through the ``dpemu.commands`` entry-point group (the
pool game adds ``shot``), so the generic tool never imports them.
"""
from __future__ import annotations

import importlib
import os

import click

# numpy's OpenBLAS starts a thread pool when numpy is imported, and each idle thread spins on
# sched_yield for about 2**28 cycles (0.1 s) before it sleeps: CPU time every dpemu process paid on
# an idle machine. dpemu's matrices are 3x3 and 4x4; batches of shots use processes, not BLAS threads.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

# subcommand -> ("module:attribute", the one-line help ``dpemu --help`` lists without importing it);
# tests/cli/test_main.py checks each line against the command's own help
_BUILTIN = {
    "check": ("emulator.cli.check:check", "Check data packs (folders or .zip files) and report problems."),
    "disasm": ("emulator.cli.disasm:disasm", "Print FUNCTION's bytecode beside its source lines."),
    "profile": ("emulator.cli.profile:profile", "Profile PACKS: report exact command counts."),
    "run": ("emulator.cli.run:run", "Emulate PACKS tick by tick."),
    "test": ("emulator.cli.test:test", "Run PackTest-format test files."),
}


def _plugins() -> dict[str, str]:
    """The installed packages' subcommands (reading every package's metadata: only when a name is
    not built in, or for the list)."""
    from importlib.metadata import entry_points

    return {ep.name: ep.value for ep in entry_points(group="dpemu.commands")}


class _LazyGroup(click.Group):
    """Imports a subcommand's module only when that subcommand runs (``--help`` lists the built-in
    ones from their one-line help, the plugins' by loading them)."""

    def _targets(self) -> dict[str, str]:
        return {**_plugins(), **{name: target for name, (target, _) in _BUILTIN.items()}}

    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted(self._targets())

    def get_command(self, ctx: click.Context, name: str) -> click.Command | None:
        target = _BUILTIN[name][0] if name in _BUILTIN else _plugins().get(name)
        if target is None:
            return None
        module, attribute = target.split(":")
        return getattr(importlib.import_module(module), attribute)

    def invoke(self, ctx: click.Context):
        """Ctrl-C anywhere in a subcommand ends with status 130 (click would print "Aborted!" and
        exit 1); the subcommands that can print what they did so far catch it first."""
        try:
            return super().invoke(ctx)
        except KeyboardInterrupt:
            click.echo("\ninterrupted", err=True)
            ctx.exit(130)

    def format_commands(self, ctx: click.Context, formatter: click.HelpFormatter) -> None:
        rows = []
        for name in self.list_commands(ctx):
            line = _BUILTIN[name][1] if name in _BUILTIN else self.get_command(ctx, name).get_short_help_str()
            rows.append((name, line))
        with formatter.section("Commands"):
            formatter.write_dl(rows)


@click.group(cls=_LazyGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="dpemu")
def main() -> None:
    """Emulate, test, profile and check Minecraft Java Edition datapacks."""
