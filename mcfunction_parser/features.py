"""Which commands, subcommands and syntax exist in which Java Edition version: the one table.

Versions are ``(major, minor, patch)`` tuples. ``since`` is the first release that has the
feature; ``until`` the first release that no longer has it (None: still present). Sources are
the "History" sections of the minecraft.wiki command pages and the snapshot changelogs (noted
per entry where the release is not obvious).
"""
from __future__ import annotations

from functools import lru_cache

Version = tuple[int, int, int]
OLDEST: Version = (1, 13, 0)

# Commands a function can contain: name -> (since, until, permission level).
# Functions are compiled at permission level 2 (server.properties function-permission-level):
# commands above that level are flagged by the parser as a warning.
COMMANDS: dict[str, tuple[Version, Version | None, int]] = {
    "advancement": (OLDEST, None, 2),
    "attribute": ((1, 16, 0), None, 2),
    "ban": (OLDEST, None, 3),
    "ban-ip": (OLDEST, None, 3),
    "banlist": (OLDEST, None, 3),
    "bossbar": (OLDEST, None, 2),
    "clear": (OLDEST, None, 2),
    "clone": (OLDEST, None, 2),
    "damage": ((1, 19, 4), None, 2),  # 23w06a
    "data": (OLDEST, None, 2),
    "datapack": (OLDEST, None, 2),
    "debug": (OLDEST, None, 3),
    "defaultgamemode": (OLDEST, None, 2),
    "deop": (OLDEST, None, 3),
    "dialog": ((1, 21, 6), None, 2),
    "difficulty": (OLDEST, None, 2),
    "effect": (OLDEST, None, 2),
    "enchant": (OLDEST, None, 2),
    "execute": (OLDEST, None, 2),
    "experience": (OLDEST, None, 2),
    "fetchprofile": ((1, 21, 9), None, 2),  # 25w34a
    "fill": (OLDEST, None, 2),
    "fillbiome": ((1, 19, 3), None, 2),  # 22w46a
    "forceload": (OLDEST, None, 2),
    "function": (OLDEST, None, 2),
    "gamemode": (OLDEST, None, 2),
    "gamerule": (OLDEST, None, 2),
    "give": (OLDEST, None, 2),
    "help": (OLDEST, None, 0),
    "item": ((1, 17, 0), None, 2),  # 20w46a replaced replaceitem
    "jfr": ((1, 18, 0), None, 4),
    "kick": (OLDEST, None, 3),
    "kill": (OLDEST, None, 2),
    "list": (OLDEST, None, 0),
    "locate": (OLDEST, None, 2),
    "locatebiome": ((1, 16, 0), (1, 19, 0), 2),  # merged into locate biome in 22w19a
    "loot": (OLDEST, None, 2),
    "me": (OLDEST, None, 0),
    "msg": (OLDEST, None, 0),
    "op": (OLDEST, None, 3),
    "pardon": (OLDEST, None, 3),
    "pardon-ip": (OLDEST, None, 3),
    "particle": (OLDEST, None, 2),
    "perf": ((1, 17, 0), None, 4),
    "place": ((1, 19, 0), None, 2),  # 22w18a replaced placefeature
    "placefeature": ((1, 18, 2), (1, 19, 0), 2),
    "playsound": (OLDEST, None, 2),
    "publish": (OLDEST, None, 4),
    "random": ((1, 20, 2), None, 2),  # 23w31a
    "recipe": (OLDEST, None, 2),
    "reload": (OLDEST, None, 2),
    "replaceitem": (OLDEST, (1, 17, 0), 2),
    "return": ((1, 20, 0), None, 2),  # 23w16a
    "ride": ((1, 19, 4), None, 2),  # 23w03a
    "rotate": ((1, 21, 2), None, 2),  # 24w35a
    "save-all": (OLDEST, None, 4),
    "save-off": (OLDEST, None, 4),
    "save-on": (OLDEST, None, 4),
    "say": (OLDEST, None, 2),
    "schedule": (OLDEST, None, 2),
    "scoreboard": (OLDEST, None, 2),
    "seed": (OLDEST, None, 2),
    "setblock": (OLDEST, None, 2),
    "setidletimeout": (OLDEST, None, 3),
    "setworldspawn": (OLDEST, None, 2),
    "spawnpoint": (OLDEST, None, 2),
    "spectate": ((1, 15, 0), None, 2),
    "spreadplayers": (OLDEST, None, 2),
    "stop": (OLDEST, None, 4),
    "stopwatch": ((1, 21, 11), None, 2),  # 25w41a
    "stopsound": (OLDEST, None, 2),
    "summon": (OLDEST, None, 2),
    "swing": ((26, 1, 0), None, 2),  # in 26.1's command tree (minecraft-data), not 1.21.11's
    "tag": (OLDEST, None, 2),
    "team": (OLDEST, None, 2),
    "teammsg": (OLDEST, None, 0),
    "teleport": (OLDEST, None, 2),
    "tell": (OLDEST, None, 0),
    "tellraw": (OLDEST, None, 2),
    "test": ((1, 21, 5), None, 2),  # 25w03a
    "tick": ((1, 20, 3), None, 3),  # 23w43a
    "time": (OLDEST, None, 2),
    "title": (OLDEST, None, 2),
    "tm": (OLDEST, None, 0),
    "tp": (OLDEST, None, 2),
    "transfer": ((1, 20, 5), None, 3),  # 24w04a
    "trigger": (OLDEST, None, 0),
    "version": ((1, 21, 6), None, 2),
    "w": (OLDEST, None, 0),
    "waypoint": ((1, 21, 6), None, 2),
    "weather": (OLDEST, None, 2),
    "whitelist": (OLDEST, None, 3),
    "worldborder": (OLDEST, None, 2),
    "xp": (OLDEST, None, 2),
}

# Syntax inside commands, keyed by a short description used in messages.
FEATURES: dict[str, tuple[Version, Version | None]] = {
    "macro lines": ((1, 20, 2), None),  # 23w31a
    "line continuation": ((1, 20, 2), None),  # 23w31a
    "world clocks": ((26, 1, 0), None),  # 26.1's tree: time of <clock>, pause, resume, rate, set <marker>
    "function arguments": ((1, 20, 2), None),  # 23w31a: function NAME {..} / with
    "return run": ((1, 20, 3), None),  # 23w31a, removed in 1.20.2-pre1, back in 23w41a
    "return fail": ((1, 20, 3), None),  # 23w44a
    "execute on": ((1, 19, 4), None),  # 23w03a
    "execute summon": ((1, 19, 4), None),  # 23w03a
    "execute positioned over": ((1, 19, 4), None),  # 23w04a
    "execute if biome": ((1, 19, 3), None),  # 22w46a
    "execute if dimension": ((1, 19, 4), None),  # 23w03a
    "execute if loaded": ((1, 19, 4), None),  # 23w03a
    "execute if function": ((1, 20, 3), None),  # 23w41a
    "execute if items": ((1, 20, 5), None),  # 24w10a
    "execute if stopwatch": ((1, 21, 11), None),  # 25w41a
    "data modify string": ((1, 19, 4), None),  # 23w03a
    "selector @n": ((1, 21, 0), None),  # 24w21a
    "scoreboard players display": ((1, 20, 3), None),  # 23w46a
    "objectives modify numberformat": ((1, 20, 3), None),  # 23w46a
    "objectives modify displayautoupdate": ((1, 20, 3), None),  # 23w46a
    "random reset": ((1, 20, 2), None),
}

# Commands whose replacement is worth naming in the error.
REPLACEMENTS = {"replaceitem": "item replace", "locatebiome": "locate biome", "placefeature": "place feature"}


def version_text(version: Version) -> str:
    major, minor, patch = version
    return f"{major}.{minor}.{patch}" if patch else f"{major}.{minor}"


def _problem(what: str, since: Version, until: Version | None, version: Version) -> str | None:
    if version < since:
        return f"{what} requires Minecraft {version_text(since)} or later (pack targets {version_text(version)})"
    if until is not None and version >= until:
        return f"{what} was removed in Minecraft {version_text(until)} (pack targets {version_text(version)})"
    return None


def command_problem(name: str, version: Version) -> str | None:
    """Why command ``name`` can't be used in ``version`` (None when it can)."""
    entry = COMMANDS.get(name)
    if entry is None:
        return f"unknown command '{name}'"
    problem = _problem(f"`{name}`", entry[0], entry[1], version)
    if problem and name in REPLACEMENTS and entry[1] is not None and version >= entry[1]:
        problem += f"; use `{REPLACEMENTS[name]}`"
    return problem


@lru_cache(maxsize=1024)
def feature_problem(feature: str, version: Version) -> str | None:
    since, until = FEATURES[feature]
    return _problem(f"`{feature}`", since, until, version)


def permission_warning(name: str) -> str | None:
    level = COMMANDS[name][2]
    if level > 2:
        return (f"`{name}` needs permission level {level}: functions are compiled at level 2, so the "
                "game won't load this function unless the server raises function-permission-level")
    return None
