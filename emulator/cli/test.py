"""``dpemu test``: run PackTest-format mcfunction tests (``data/<ns>/test/**.mcfunction``)."""
from __future__ import annotations

import sys

import click

from emulator.cli.outcome import exit_status, interruptible
from emulator.cli.params import OutputPath, write_output
from emulator.testing import Summary, discover, run_suite
from emulator.testing.discovery import DiscoveryError, selected
from emulator.testing.junit import junit_xml


@click.command("test")
@click.argument("paths", nargs=-1, required=True, type=click.Path(exists=True))  # packs, folders, files
@click.option("-k", "pattern", metavar="PATTERN", help="Only tests whose id contains PATTERN.")
@click.option("--junit", "junit_file", metavar="FILE", type=OutputPath(stdout=False), help="Write JUnit XML.")
@click.option("--backend", type=click.Choice(["numba", "python"]), default="numba", show_default=True)
@click.option("--strict", is_flag=True, help="A runtime error during a test (unknown function, division by zero ...) fails it.")
def test(paths, pattern, junit_file, backend, strict) -> None:
    """Run PackTest-format test files.

    PATHS: packs as folders or .zip files, folders in a pack, or test files."""
    try:
        files = discover(list(paths))
    except DiscoveryError as error:
        raise click.UsageError(str(error)) from None
    if files and not selected(files, pattern):
        raise click.UsageError(f"-k {pattern!r} matches none of the {len(files)} tests under {', '.join(paths)}")

    def loaded(packs) -> None:
        for diag in packs.errors:
            click.echo(diag.format(), err=True)

    summary = Summary()
    with interruptible() as stopped:
        def reported(result) -> None:  # each test's line as it ends is the progress
            summary.results.append(result)
            click.echo(result.report())

        run_suite(files, backend, pattern, on_result=reported, on_load=loaded, strict=strict)
    if not summary.results and not stopped[0]:
        click.echo("no test files (data/<ns>/test/**.mcfunction" + (f" matching -k {pattern!r}" if pattern else "")
                   + ") under " + ", ".join(paths), err=True)
    written = not junit_file or write_output(junit_file, junit_xml(summary))
    click.echo(summary.line())
    sys.exit(exit_status(not summary.ok, written=written, interrupted=stopped[0]))
