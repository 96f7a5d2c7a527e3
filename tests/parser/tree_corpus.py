"""Lines generated from the game's command tree (1.21.11, mecha's "1.21"), for the agreement test:
every executable path of every command with a valid value for each argument, and for each argument
of such a path the same line with an invalid value there.

The values are the parser type's (with its properties: an integer's minimum, a selector's amount
and type, a registry); a redirect to ``execute`` ends with `` run say x``, another redirect (``tp``
to ``teleport``, ``run``) goes on in the command it names, once.
"""
from __future__ import annotations

from mcfunction_parser.gamedata import command_tree

RELEASE = (1, 21, 11)

# parser -> (valid value, invalid value or None for a type that takes any text there)
_VALUES = {
    "brigadier:bool": ("true", "maybe"),
    "brigadier:double": ("1.5", "x"),
    "brigadier:float": ("1.5", "x"),
    "minecraft:nbt_path": ("a.b[0]", "a..b"),
    "minecraft:block_pos": ("1 2 3", "1 2 x"),
    "minecraft:resource_location": ("ns:id", "NS:Id"),
    "minecraft:objective": ("obj", "o!"),
    "minecraft:vec3": ("1 2.5 3", "1 2"),
    "minecraft:item_stack": ("minecraft:stone", "stone["),
    "minecraft:component": ('{"text":"a"}', '{"text":'),
    "minecraft:nbt_tag": ("{a:1b}", "{a:"),
    "minecraft:loot_table": ("ns:loot", "NS:loot"),
    "minecraft:block_predicate": ("#minecraft:logs", "stone["),
    "minecraft:item_slot": ("container.0", "nowhere.0"),
    "minecraft:message": ("hello there", None),
    "minecraft:game_profile": ("Steve", "@x"),
    "minecraft:dimension": ("minecraft:overworld", "Bad:x"),
    "minecraft:loot_modifier": ("ns:mod", "NS:mod"),
    "minecraft:item_predicate": ("*", "stone["),
    "minecraft:nbt_compound_tag": ("{a:1}", "[1]"),
    "minecraft:function": ("ns:f", "ns:Bad"),
    "minecraft:rotation": ("90 0", "90"),
    "minecraft:column_pos": ("1 2", "1.5 2"),
    "minecraft:team": ("red_team", "t!"),
    "minecraft:entity_anchor": ("eyes", "nose"),
    "minecraft:item_slots": ("container.*", "nowhere.*"),
    "minecraft:int_range": ("1..2", "a"),
    "minecraft:gamemode": ("survival", "flying"),
    "minecraft:loot_predicate": ("ns:pred", "NS:pred"),
    "minecraft:float_range": ("1..2.5", "a"),
    "minecraft:block_state": ("minecraft:stone", "stone["),
    "minecraft:style": ('{"bold":true}', '{"bold":'),
    "minecraft:vec2": ("1 2", "1"),
    "minecraft:color": ("red", "reddish"),
    "minecraft:dialog": ("ns:dialog", "NS:dialog"),
    "minecraft:swizzle": ("xz", "xx"),
    "minecraft:heightmap": ("world_surface", "sky"),
    "minecraft:uuid": ("0-0-0-0-1", "zz"),
    "minecraft:particle": ("minecraft:flame", "minecraft:flame{"),
    "minecraft:template_rotation": ("none", "spin"),
    "minecraft:template_mirror": ("none", "flip"),
    "minecraft:objective_criteria": ("dummy", "dummy!"),
    "minecraft:scoreboard_slot": ("sidebar", "top"),
    "minecraft:operation": ("+=", "**"),
    "minecraft:hex_color": ("FF0000", "red"),
}
# a registry's id for minecraft:resource and its kin
_IDS = {"minecraft:attribute": "minecraft:armor", "minecraft:damage_type": "minecraft:generic",
        "minecraft:enchantment": "minecraft:sharpness", "minecraft:entity_type": "minecraft:pig",
        "minecraft:mob_effect": "minecraft:speed", "minecraft:worldgen/biome": "minecraft:plains",
        "minecraft:point_of_interest_type": "minecraft:home"}


def _value(node: dict) -> tuple[str, str | None]:
    parser, props = node["parser"], node.get("properties") or {}
    if parser in ("brigadier:integer", "minecraft:time"):
        low = props.get("min")
        valid = str(max(low, 1) if low is not None and props.get("max", 1) >= 1 else (low if low is not None else 1))
        if parser == "minecraft:time":
            return valid + "t", "-1t" if low is not None else "1x"
        return valid, str(low - 1) if low is not None else "1.5"
    if parser == "brigadier:string":
        kind = props.get("type")
        return {"word": ("word", "a\"b"), "phrase": ('"a b"', '"a b'), "greedy": ("any text here", None)}[kind]
    if parser == "minecraft:entity":
        single, players = props.get("amount") == "single", props.get("type") == "players"
        valid = ("@p" if players else "@s") if single else ("@a" if players else "@e")
        return valid, "@e" if single or players else "@x"
    if parser == "minecraft:score_holder":
        return ("@s", "@e") if props.get("amount") == "single" else ("*", "@x")
    if parser == "minecraft:resource":
        return _IDS[props["registry"]], "Bad:id"
    if parser in ("minecraft:resource_key", "minecraft:resource_selector"):
        return "ns:key", "NS:key"
    if parser == "minecraft:resource_or_tag":
        return _IDS[props["registry"]], "#Bad:tag"
    if parser == "minecraft:resource_or_tag_key":
        return "#ns:tag", "#Bad:tag"
    return _VALUES[parser]


def _paths(root: dict, node: dict, words: list, out: list) -> None:
    """Every executable path below ``node``: its words, each as (valid text, invalid text or None)."""
    if node.get("executable"):
        out.append(words)
    redirect = node.get("redirect")
    if redirect == ["execute"]:  # a subcommand: the chain goes on
        out.append(words + [("run say x", None)])
        return
    if redirect:  # an alias: the command it names
        _paths(root, root["children"][redirect[0]], words, out)
        return
    children = node.get("children") or {}
    if not children and not node.get("executable"):  # `run`: any command (the root)
        out.append(words + [("say x", None)])
    for name, child in children.items():
        _paths(root, child, words + [(name, None) if child["type"] == "literal" else _value(child)], out)


def tree_lines() -> tuple[list[str], list[str]]:
    """(lines every path's valid values make, lines with one argument's value made invalid)."""
    root = command_tree(RELEASE)
    valid: dict[str, None] = {}
    invalid: dict[str, None] = {}
    for name, node in root["children"].items():
        found: list = []
        _paths(root, node, [(name, None)], found)
        for words in found:
            valid[" ".join(word for word, _ in words)] = None
            for i, (_, bad) in enumerate(words):
                if bad is not None:
                    invalid[" ".join(bad if j == i else word for j, (word, _) in enumerate(words))] = None
    return list(valid), list(invalid)
