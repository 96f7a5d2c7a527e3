"""The ``dpemu`` command line. Each subcommand lives in its own ``cli_<name>.py`` module."""
from __future__ import annotations

import click


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="dpemu")
def main() -> None:
    """Emulate, test, profile and check Minecraft Java Edition datapacks."""


# Subcommands register themselves here, one line each:
from emulator.cli_check import check; main.add_command(check)  # noqa: E402,E702
from emulator.cli_run import run; main.add_command(run)  # noqa: E402,E702
from emulator.cli_disasm import disasm; main.add_command(disasm)  # noqa: E402,E702
from emulator.cli_test import test; main.add_command(test)  # noqa: E402,E702
from emulator.cli_profile import profile; main.add_command(profile)  # noqa: E402,E702
from emulator.cli_shot import shot; main.add_command(shot)  # noqa: E402,E702
