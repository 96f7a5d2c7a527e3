"""What ``help`` prints: Brigadier's smart usage over the game's command tree (the report's shape,
:func:`..gamedata.command_tree`), for a source of a given permission level.

HelpCommand: ``help`` sends ``/`` + the smart usage of each of the root's children; ``help TEXT``
parses TEXT (CommandDispatcher.parse) and sends ``/TEXT `` + the smart usage of each child of the
last node it reached, failing (``commands.help.failed``) when it reached none. The usage rules are
CommandDispatcher.getSmartUsage: a node's usage text (a literal's name, ``<name>`` for an
argument), ``[...]`` round what may be left out (the children of an executable node), one child
followed, several shown as ``(a|b)`` or ``[a|b]``, a redirect as ``-> target`` or ``...`` (to the
root: a childless, non-executable literal in the report, where the game writes no path for it).

The report lists a node's children sorted by name, the game keeps them in the order the commands
registered them: where that order shows (several messages, an alternation of several children),
:class:`OrderUnknown` is raised rather than a guess.
"""
from __future__ import annotations

# the level functions and command blocks run at (ServerFunctionManager, BaseCommandBlock)
GAMEMASTERS = 2
# CommandSourceStack permission levels as the report names them (Commands.LEVEL_*)
_LEVELS = {"all": 0, "moderators": 1, "gamemasters": 2, "admins": 3, "owners": 4}
# before the report carried permissions (1.21): the root commands that need more than level 2
_ABOVE_GAMEMASTERS = frozenset({
    "ban", "ban-ip", "banlist", "debug", "deop", "jfr", "kick", "op", "pardon", "pardon-ip", "perf", "publish",
    "save-all", "save-off", "save-on", "setidletimeout", "stop", "tick", "transfer", "whitelist"})


class OrderUnknown(Exception):
    """The messages depend on the order the game registered sibling nodes in."""


def help_messages(root: dict, text: str | None, level: int = GAMEMASTERS) -> list[str] | None:
    """The messages ``help`` (``text`` None) or ``help TEXT`` sends, in order; None when TEXT names
    no command the source may use (the command fails)."""
    walk = _Walk(root, level)
    node = root if text is None else walk.last_node(text)
    if node is None:
        return None
    prefix = "/" if text is None else f"/{text} "
    return [prefix + usage for usage in walk.child_usages(node, root=text is None)]


def help_count(root: dict, text: str | None, level: int = GAMEMASTERS) -> int | None:
    """How many messages :func:`help_messages` sends (the command's result), which the order of
    the children does not change; None when the command fails."""
    walk = _Walk(root, level)
    node = root if text is None else walk.last_node(text)
    return None if node is None else len(walk.children(node, text is None))


class _Walk:
    def __init__(self, root: dict, level: int) -> None:
        self.root, self.level = root, level
        self.unmarked = not any("permissions" in node for node in root["children"].values())

    def can_use(self, name: str, node: dict, at_root: bool) -> bool:
        required = node.get("permissions", {}).get("permission", {}).get("level")
        if required is None:
            return not (at_root and self.unmarked and name in _ABOVE_GAMEMASTERS and self.level < 3)
        return _LEVELS.get(required, 4) <= self.level

    def children(self, node: dict, at_root: bool = False) -> list[tuple[str, dict]]:
        return [(n, c) for n, c in node.get("children", {}).items() if self.can_use(n, c, at_root)]

    def last_node(self, text: str) -> dict | None:
        """The last node of CommandDispatcher.parse's context for ``text`` (a redirect's target is
        read into a child context), when the words before it are literals: reading an argument is
        not done here (ValueError)."""
        node, at_root = self.root, True
        reached = None
        for word in text.split(" "):
            literal = dict(self.children(node, at_root)).get(word)
            if literal is None or literal.get("type") != "literal":
                if any(c.get("type") == "argument" for _, c in self.children(node, at_root)):
                    raise ValueError(f"help reading an argument of `{text}`")
                break
            reached = literal
            if "redirect" in literal:  # what follows is read into a child context
                break
            node, at_root = literal, False
        return reached

    def child_usages(self, node: dict, root: bool = False) -> list[str]:
        """CommandDispatcher.getSmartUsage(node, source): each usable child's usage."""
        optional = bool(node.get("executable"))
        usages = [self.usage(name, child, optional, False) for name, child in self.children(node, root)]
        if len(usages) > 1:
            raise OrderUnknown("several messages")
        return usages

    def usage(self, name: str, node: dict, optional: bool, deep: bool) -> str:
        own = _usage_text(name, node)
        own = f"[{own}]" if optional else own
        child_optional = bool(node.get("executable"))
        if deep:
            return own
        if "redirect" in node:
            return f"{own} -> {node['redirect'][-1]}" if node["redirect"] else f"{own} ..."
        if node.get("type") == "literal" and not node.get("children") and not child_optional:
            return f"{own} ..."  # a redirect to the root (``execute run``)
        children = self.children(node)
        if len(children) == 1:
            child_name, child = children[0]
            return f"{own} {self.usage(child_name, child, child_optional, child_optional)}"
        if len(children) > 1:
            distinct = list(dict.fromkeys(self.usage(n, c, child_optional, True) for n, c in children))
            if len(distinct) == 1:
                return f"{own} {f'[{distinct[0]}]' if child_optional else distinct[0]}"
            raise OrderUnknown(f"the alternatives after {own}")
        return own


def _usage_text(name: str, node: dict) -> str:
    return f"<{name}>" if node.get("type") == "argument" else name
