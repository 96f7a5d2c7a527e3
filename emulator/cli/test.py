"""``dpemu test``: run PackTest-format mcfunction tests (``data/<ns>/test/**.mcfunction``)."""
from __future__ import annotations

import sys

import click

from emulator.testing import discover, run_suite
from emulator.testing.discovery import DiscoveryError
from emulator.testing.junit import junit_xml


@click.command("test")
@click.argument("paths", nargs=-1, required=True, type=click.Path(exists=True))
@click.option("-k", "pattern", metavar="PATTERN", help="Only tests whose id contains PATTERN.")
@click.option("--junit", "junit_file", metavar="FILE", type=click.Path(dir_okay=False), help="Write JUnit XML.")
@click.option("--backend", type=click.Choice(["numba", "python"]), default="numba", show_default=True)
def test(paths, pattern, junit_file, backend) -> None:
    """Run the test files in PATHS (packs, folders in a pack, or test files)."""
    try:
        files = discover(list(paths))
    except DiscoveryError as error:
        raise click.UsageError(str(error)) from None

    def loaded(packs) -> None:
        for diag in packs.errors:
            click.echo(diag.format(), err=True)

    summary = run_suite(files, backend, pattern, on_result=lambda r: click.echo(r.report()), on_load=loaded)
    if not summary.results:
        click.echo("no test files (data/<ns>/test/**.mcfunction" + (f" matching -k {pattern!r}" if pattern else "")
                   + ") under " + ", ".join(paths), err=True)
    if junit_file:
        with open(junit_file, "w", encoding="utf-8") as handle:
            handle.write(junit_xml(summary))
    click.echo(summary.line())
    sys.exit(0 if summary.ok else 1)
