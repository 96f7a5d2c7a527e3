"""The ``dpemu`` command line: one module per subcommand in this package, loaded when used.

Other installed packages add subcommands through the ``dpemu.commands`` entry-point group (the
pool game adds ``shot``), so the generic tool never imports them.
"""
from __future__ import annotations

import importlib
from importlib.metadata import entry_points

import click

# subcommand -> "module:attribute"
_BUILTIN = {
    "check": "emulator.cli.check:check",
    "run": "emulator.cli.run:run",
    "disasm": "emulator.cli.disasm:disasm",
    "test": "emulator.cli.test:test",
    "profile": "emulator.cli.profile:profile",
}


def _plugins() -> dict[str, str]:
    return {ep.name: ep.value for ep in entry_points(group="dpemu.commands")}


class _LazyGroup(click.Group):
    """Imports a subcommand's module only when that subcommand (or the full help) is asked for."""

    def _targets(self) -> dict[str, str]:
        return {**_plugins(), **_BUILTIN}

    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted(self._targets())

    def get_command(self, ctx: click.Context, name: str) -> click.Command | None:
        target = self._targets().get(name)
        if target is None:
            return None
        module, attribute = target.split(":")
        return getattr(importlib.import_module(module), attribute)


@click.group(cls=_LazyGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="dpemu")
def main() -> None:
    """Emulate, test, profile and check Minecraft Java Edition datapacks."""
