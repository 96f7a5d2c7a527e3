"""Command-line values every subcommand validates the same way: finite numbers, and output paths
checked before the work starts (a write that still fails is reported, and what was computed is kept)."""
from __future__ import annotations

import math
import os
from pathlib import Path

import click


class FiniteFloat(click.ParamType):
    """A float that is a number: ``nan``, ``inf`` and literals past the double range are refused."""

    name = "number"

    def convert(self, value, param, ctx):
        if isinstance(value, float):
            number = value
        else:
            try:
                number = float(value)
            except ValueError:
                self.fail(f"{value!r} is not a number", param, ctx)
        if not math.isfinite(number):
            self.fail(f"{value!r} is not a finite number", param, ctx)
        return number


class OutputPath(click.ParamType):
    """A file to write: its folder must exist and be writable, checked when the options are read;
    ``-`` means standard output where ``stdout`` allows it."""

    name = "file"

    def __init__(self, stdout: bool = True) -> None:
        self.stdout = stdout

    def convert(self, value, param, ctx):
        text = os.fspath(value)
        if text == "-":
            if self.stdout:
                return text
            self.fail("'-' (standard output) is not possible here: give a file name", param, ctx)
        path = Path(text)
        if path.is_dir():
            self.fail(f"{text} is a folder, not a file", param, ctx)
        folder = path.parent
        if not folder.is_dir():
            self.fail(f"{text}: the folder {folder} does not exist", param, ctx)
        if not os.access(folder, os.W_OK) or (path.exists() and not os.access(path, os.W_OK)):
            self.fail(f"{text}: not writable", param, ctx)
        return text


def write_output(path: str, text: str) -> bool:
    """Write ``text`` to ``path`` (``-``: standard output); False, with the reason on stderr, when
    the write fails."""
    if path == "-":
        click.echo(text)
        return True
    try:
        Path(path).write_text(text)
    except OSError as error:
        click.echo(f"error: could not write {path}: {error.strerror or error}", err=True)
        return False
    return True


class PackPath(click.ParamType):
    """A pack: a folder, or a .zip file that opens as one (a broken archive says so)."""

    name = "pack"

    def convert(self, value, param, ctx):
        path = Path(value)
        if path.is_dir():
            return path
        if not path.exists():
            self.fail(f"'{path}' does not exist", param, ctx)
        from mcfunction_parser.pack.loader import zip_problem  # the parser, only when a pack is named

        problem = zip_problem(path)
        if problem:
            self.fail(f"'{path}' {problem}", param, ctx)
        return path



class GameJar(click.ParamType):
    """The game's client or server jar, checked when the option is read (its vanilla data is read
    without Java: :func:`mcfunction_parser.gamedata.vanilla_tags.open_game_jar`)."""

    name = "jar"

    def convert(self, value, param, ctx):
        from mcfunction_parser.gamedata.game_jars import AUTO
        from mcfunction_parser.gamedata.vanilla_tags import GameJarError, open_game_jar

        if value == AUTO:  # found or downloaded once the packs' release is known
            return value
        try:
            open_game_jar(value)
        except GameJarError as error:
            self.fail(str(error), param, ctx)
        return str(value)


# One definition of --game-jar for every subcommand that loads packs (run, profile, test, check).
game_jar_option = click.option(
    "--game-jar", type=GameJar(), metavar="JAR|auto", envvar="DPEMU_GAME_JAR",
    help="The game's client or server jar: its vanilla tags (#minecraft:...), loot tables and recipes load under "
         "the packs'. 'auto': the launcher's jar of the packs' release, else downloaded from Mojang once and cached.")
