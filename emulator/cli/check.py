"""``dpemu check PACK... [--json] [--mc VERSION] [--with PACK] [--packtest]``: lint data packs.

Exit status: 0 when there is no error (warnings and infos allowed), 1 when there are errors,
2 for usage errors (a path that is not a pack folder or .zip file, an unknown ``--mc`` version).
"""
from __future__ import annotations

import contextlib
import json
import sys
from pathlib import Path

import click

from emulator.cli.outcome import INTERRUPTED, Passes
from emulator.cli.params import PackPath, game_jar_option
from mcfunction_parser.check import check_releases
from mcfunction_parser.dialect import packtest_commands
from mcfunction_parser.diagnostics import ERROR
from mcfunction_parser.pack.versions import parse_version_set


def _validate_versions(ctx: click.Context, param: click.Parameter, value: str | None) -> list | None:
    if value is None:
        return None
    try:
        return parse_version_set(value)
    except ValueError as exc:
        raise click.BadParameter(str(exc)) from None


@click.command()
@click.argument("packs", nargs=-1, required=True, type=PackPath())
@click.option("--json", "as_json", is_flag=True, help="Print one JSON object instead of text.")
@click.option("--mc", "releases", metavar="VERSION[..VERSION|,VERSION...]", callback=_validate_versions,
              help="Game versions to check for: 1.21.4, a range 1.16.5..1.21.11 or a list 1.20.4,1.21.4; "
                   "default: the range the packs declare, else their own version.")
@click.option("--with", "with_packs", multiple=True, type=PackPath(), metavar="PACK",
              help="A pack expected beside these at run time (a library, another module): loaded "
                   "first, its own findings not reported. Repeatable.")
@click.option("--packtest", is_flag=True,
              help="Check as on a test server with PackTest: its assert, fail and succeed are commands in every function.")
@game_jar_option
def check(packs: tuple[Path, ...], as_json: bool, releases: list | None, with_packs: tuple[Path, ...],
          packtest: bool, game_jar: str | None) -> None:
    """Check data packs (folders or .zip files) and report problems.

    Packs load in the order given; later ones override earlier ones."""
    bar = Passes("parsing")
    try:
        with packtest_commands() if packtest else contextlib.nullcontext():
            result = check_releases(packs, releases, with_packs, on_function=bar, game_jar=game_jar)
    except KeyboardInterrupt:
        bar.close()
        click.echo("\ninterrupted: nothing was checked to the end", err=True)
        sys.exit(INTERRUPTED)
    except Exception as exc:  # a bug in dpemu must still end with a message, not a traceback
        click.echo(f"dpemu check: internal error: {type(exc).__name__}: {exc}", err=True)
        sys.exit(1)
    bar.close()
    if as_json:
        click.echo(json.dumps(result.to_json(), ensure_ascii=False))
    else:
        for diagnostic in result.diagnostics:
            click.echo(diagnostic.format())
        click.echo(result.summary())
    sys.exit(1 if result.of(ERROR) else 0)
