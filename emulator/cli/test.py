"""``dpemu test``: run PackTest-format mcfunction tests (``data/<ns>/test/**.mcfunction``)."""
from __future__ import annotations

import sys

import click

from emulator.cli.outcome import exit_status, interruptible
from emulator.cli.params import OutputPath, game_jar_option, write_output
from emulator.testing import Summary, discover, run_suite
from emulator.testing.discovery import DiscoveryError, selected
from emulator.testing.junit import junit_xml


@click.command("test")
@click.argument("paths", nargs=-1, required=True, type=click.Path(exists=True))  # packs, folders, files
@click.option("-k", "pattern", metavar="PATTERN", help="Only tests whose id contains PATTERN.")
@click.option("--junit", "junit_file", metavar="FILE", type=OutputPath(stdout=False), help="Write JUnit XML.")
@click.option("--backend", type=click.Choice(["numba", "python"]), default="numba", show_default=True)
@click.option("--strict", is_flag=True, help="A runtime error during a test (unknown function, division by zero ...) fails it.")
@click.option("--with", "with_packs", multiple=True, metavar="PACK", type=click.Path(exists=True),
              help="A pack loaded beneath each pack under test (a library, another module it needs); repeatable.")
@click.option("--together", is_flag=True,
              help="Load every pack under test into one world and run all their tests there, as a collection's CI does.")
@click.option("--isolate", is_flag=True,
              help="Run each test alone in a fresh world (default: one world, batches in turn, a batch's tests together, "
                   "as the game test server).")
@click.option("--allow-unmodelled", is_flag=True,
              help="A test meeting something the emulator does not model passes or fails as it ran (default: inconclusive).")
@click.option("--log", "show_log", is_flag=True,
              help="Print under each test the output lines while it ran (say, tellraw ...: the chat it could see).")
@game_jar_option
def test(paths, pattern, junit_file, backend, strict, with_packs, together, isolate, allow_unmodelled,
         show_log, game_jar) -> None:
    """Run PackTest-format test files.

    PATHS: packs as folders or .zip files, folders in a pack, or test files."""
    try:
        files = discover(list(paths))
    except DiscoveryError as error:
        raise click.UsageError(str(error)) from None
    if files and not selected(files, pattern):
        raise click.UsageError(f"-k {pattern!r} matches none of the {len(files)} tests under {', '.join(paths)}")

    shown: set[str] = set()

    def loaded(packs) -> None:  # the load's errors and pack.mcmeta warnings, each once
        for diag in [*packs.errors, *(w for w in packs.warnings if w.path.endswith("pack.mcmeta"))]:
            text = diag.format()
            if text not in shown:
                shown.add(text)
                click.echo(text, err=True)

    summary = Summary()
    with interruptible() as stopped:
        def reported(result) -> None:  # each test's line as it ends is the progress
            summary.results.append(result)
            click.echo(result.report(log=show_log))

        run_suite(files, backend, pattern, on_result=reported, on_load=loaded, strict=strict,
                  with_packs=with_packs, together=together, allow_unmodelled=allow_unmodelled, game_jar=game_jar,
                  isolate=isolate)
    if not summary.results and not stopped[0]:
        click.echo("no test files (data/<ns>/test/**.mcfunction" + (f" matching -k {pattern!r}" if pattern else "")
                   + ") under " + ", ".join(paths), err=True)
    written = not junit_file or write_output(junit_file, junit_xml(summary))
    click.echo(summary.line())
    sys.exit(exit_status(not summary.ok, written=written, interrupted=stopped[0]))
