"""Which game rules a release has and their value types, read from its command tree.

GameRuleCommand registers one literal per rule under ``gamerule``, its ``value`` argument a
``brigadier:bool`` or ``brigadier:integer`` (with the rule's bounds from 1.21.11, when the rules
became snake_case and took a ``minecraft:`` prefix). So the release's own tree decides: a rule it
lacks is an error. A release checked against another release's tree (1.13 – 1.15 against 1.16.5's,
a release newer than every shipped tree) only warns, since that tree is not the game's for it.
"""
from __future__ import annotations

from .. import gamedata
from ..features import version_text
from .tree import root_for

SNAKE_CASE_RULES = (1, 21, 11)  # 25w44a renamed every rule
_KINDS = {"brigadier:bool": "bool", "brigadier:integer": "int"}


def _rules(version) -> dict[str, dict]:
    root = root_for(version)
    return {} if root is None else root["children"].get("gamerule", {}).get("children", {})


def _value(node: dict) -> dict:
    return node.get("children", {}).get("value", {})


def rule_type(rule: str, version) -> tuple[str | None, str | None]:
    """The rule's value type (``"bool"`` or ``"int"``) and None; None and why the release has no
    such rule; or (None, None) when no tree of the release's own can tell (a warning)."""
    node = _rules(version).get(rule)
    if node is not None:
        return _KINDS.get(_value(node).get("parser")), None
    if root_for(version) is None or gamedata.stand_in(version) is not None:
        return None, None
    return None, _missing(rule, version)


def _missing(rule: str, version) -> str:
    """Why ``version``'s tree lacks ``rule``: a rule of a later or an earlier release, or none."""
    having = [release for release in gamedata.shipped_trees() if rule in _rules(release)]
    if version >= SNAKE_CASE_RULES and having and having[-1] < SNAKE_CASE_RULES:
        return f"unknown game rule '{rule}' (game rules are snake_case from Minecraft {version_text(SNAKE_CASE_RULES)})"
    later = [release for release in having if release > version]
    if later:
        return (f"game rule '{rule}' is not in Minecraft {version_text(version)}: the command tree of "
                f"{version_text(later[0])} has it")
    if having:
        return (f"game rule '{rule}' is gone from Minecraft {version_text(version)}: last in the command tree "
                f"of {version_text(having[-1])}")
    return f"unknown game rule '{rule}'"


def int_bounds(rule: str, version) -> dict:
    """The bounds the release's tree gives an integer rule's value (from 1.21.11: min and max)."""
    value = _value(_rules(version).get(rule) or {})
    props = value.get("properties") or {} if value.get("parser") == "brigadier:integer" else {}
    return {name: props[key] for name, key in (("lo", "min"), ("hi", "max")) if key in props}


def unknown_warning(rule: str, version) -> str:
    """The warning for a rule no tree of the release's own can judge."""
    if root_for(version) is None:
        return f"unknown game rule '{rule}' (no command tree for {version_text(version)})"
    return (f"unknown game rule '{rule}' (not in the command tree of "
            f"{version_text(gamedata.tree_release(version))}, which stands in for {version_text(version)})")
