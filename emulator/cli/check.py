"""``dpemu check PACK... [--json] [--mc VERSION]``: lint data packs.

Exit status: 0 when there is no error (warnings and infos allowed), 1 when there are errors,
2 for usage errors (a path that is not a pack folder or .zip file, an unknown ``--mc`` version).
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

import click

from emulator.cli.params import PackPath
from mcfunction_parser.check import check_packs
from mcfunction_parser.diagnostics import ERROR
from mcfunction_parser.pack.versions import pack_format_for_version, parse_mc_version


def _validate_version(ctx: click.Context, param: click.Parameter, value: str | None) -> str | None:
    if value is not None:
        try:
            pack_format_for_version(parse_mc_version(value))
        except ValueError as exc:
            raise click.BadParameter(str(exc)) from None
    return value


@click.command()
@click.argument("packs", nargs=-1, required=True, type=PackPath())
@click.option("--json", "as_json", is_flag=True, help="Print one JSON object instead of text.")
@click.option("--mc", "mc_version", metavar="VERSION", callback=_validate_version,
              help="Game version to check for (e.g. 1.21.4); default: the packs' own.")
def check(packs: tuple[Path, ...], as_json: bool, mc_version: str | None) -> None:
    """Check data packs (folders or .zip files, loaded in the order given, later ones
    override) and report problems."""
    try:
        result = check_packs(packs, mc_version)
    except Exception as exc:  # a bug in dpemu must still end with a message, not a traceback
        click.echo(f"dpemu check: internal error: {type(exc).__name__}: {exc}", err=True)
        sys.exit(1)
    if as_json:
        click.echo(json.dumps(result.to_json(), ensure_ascii=False))
    else:
        for diagnostic in result.diagnostics:
            click.echo(diagnostic.format())
        click.echo(result.summary())
    sys.exit(1 if result.of(ERROR) else 0)
