"""Write a realistic datapack of generated .mcfunction files (all valid for Minecraft 1.21).

Every command family the parser models appears, in roughly the proportions of this project's pool
pack (about half scoreboard, a third execute), plus comments, blank lines, continuation and macro
lines and generic commands.
Usage: ``python bench/corpus.py DEST [LINES]`` or ``write_corpus(dest_dir, lines, seed)``.
"""
from __future__ import annotations

import json
import random
import sys
from pathlib import Path

NAMESPACE = "bench"
PACK_FORMAT = 48  # 1.21
OBJECTIVES = ("pos_x", "pos_y", "vel_x", "vel_y", "spin", "tmp", "const", "timer", "state", "id")
HOLDERS = ("@s", "#tmp", "$ball", "#c100", "@e[tag=ball,limit=1]", ".x", "Steve")
TAGS = ("ball", "cue", "moving", "pocketed", "marker", "table")
OPS = ("=", "+=", "-=", "*=", "/=", "%=", "<", ">", "><")


def _sel(rng: random.Random) -> str:
    return rng.choice((
        "@s", "@a", "@p", "@r", "@n",
        f"@e[type=minecraft:marker,tag={rng.choice(TAGS)}]",
        f"@e[tag={rng.choice(TAGS)},tag=!{rng.choice(TAGS)},limit={rng.randint(1, 9)},sort=nearest]",
        f"@e[scores={{{rng.choice(OBJECTIVES)}={rng.randint(-5, 0)}..{rng.randint(1, 50)}}},"
        f"distance=..{rng.randint(1, 30)}]",
        f"@a[x=0,y=64,z=0,dx=10,dy=5,dz=10,gamemode=!spectator]",
        f'@e[type=armor_stand,name="Ball {rng.randint(1, 15)}",nbt={{Tags:["{rng.choice(TAGS)}"]}}]',
    ))


def _single(rng: random.Random) -> str:
    return rng.choice(("@s", "@p", "@n[type=marker]", f"@e[tag={rng.choice(TAGS)},limit=1]"))


def _holder(rng: random.Random) -> str:
    return rng.choice(HOLDERS)


def _obj(rng: random.Random) -> str:
    return rng.choice(OBJECTIVES)


def _pos(rng: random.Random) -> str:
    return rng.choice((
        "~ ~ ~", f"~{rng.randint(-3, 3)} ~1.5 ~", f"^ ^ ^{rng.randint(1, 5)}",
        f"{rng.randint(-100, 100)} 64 {rng.randint(-100, 100)}",
        f"{rng.uniform(-50, 50):.3f} {rng.uniform(60, 70):.2f} {rng.uniform(-50, 50):.3f}",
    ))


def _block_pos(rng: random.Random) -> str:
    return rng.choice(("~ ~-1 ~", f"{rng.randint(-100, 100)} 63 {rng.randint(-100, 100)}", "~1 ~ ~-1"))


def _path(rng: random.Random) -> str:
    return rng.choice(("Pos[0]", "Motion[1]", "data.balls[0].x", "data.balls[-1]", 'Inventory[{Slot:0b}].id',
                       "Tags", "data.state", 'data."quoted key".v', "Rotation[0]", "data.list[]", "{a:1b}.data"))


def _storage(rng: random.Random) -> str:
    return rng.choice((f"{NAMESPACE}:physics", f"{NAMESPACE}:tmp", "minecraft:global"))


def _snbt(rng: random.Random) -> str:
    return rng.choice(("{a:1b,b:2s,c:3,d:4L,e:1.5f,f:2.5d,g:\"text\",h:[1,2,3],i:[I;1,2,3],j:{k:true}}",
                       "{Tags:[\"ball\",\"moving\"],NoGravity:1b,Invisible:1b}", "{x:0,y:0,z:0}", "[1.0d,2.0d,3.0d]",
                       f"{rng.randint(-1000, 1000)}", "'single quoted'", "[]", "{}",
                       "{CustomName:'{\"text\":\"Ball\"}',Marker:1b}"))


def _data_target(rng: random.Random) -> str:
    return rng.choice((f"entity {_single(rng)}", f"storage {_storage(rng)}", f"block {_block_pos(rng)}"))


def _execute_prefix(rng: random.Random) -> str:
    parts = []
    for _ in range(rng.choices((1, 2, 3, 4), (60, 25, 10, 5))[0]):
        if rng.random() < 0.4:  # the most common subcommand by far in physics packs
            parts.append(f"if score {_holder(rng)} {_obj(rng)} matches {rng.choice(('..-1', '0', '1..', '5..9'))}")
            continue
        parts.append(rng.choice((
            f"as {_sel(rng)}", f"at {_sel(rng)}", f"positioned {_pos(rng)}", f"positioned as {_single(rng)}",
            "positioned over motion_blocking", f"rotated {rng.randint(-180, 180)} {rng.randint(-90, 90)}",
            f"rotated as {_single(rng)}", f"facing {_pos(rng)}", f"facing entity {_single(rng)} eyes",
            "anchored eyes", "align xz", "in minecraft:overworld", "on passengers", "summon marker",
            f"if score {_holder(rng)} {_obj(rng)} matches {rng.randint(0, 9)}..{rng.randint(10, 99)}",
            f"unless score {_holder(rng)} {_obj(rng)} {rng.choice(('<', '<=', '=', '>=', '>'))} "
            f"{_holder(rng)} {_obj(rng)}",
            f"if entity {_sel(rng)}", f"if data {_data_target(rng)} {_path(rng)}",
            f"unless block {_block_pos(rng)} minecraft:stone_slab[type=top]", "if block ~ ~ ~ #minecraft:logs",
            f"if function {NAMESPACE}:util/check", f"if predicate {NAMESPACE}:is_moving", "if loaded ~ ~ ~",
            "if dimension minecraft:the_nether", "if biome ~ ~ ~ minecraft:plains",
            "if blocks ~ ~ ~ ~1 ~1 ~1 0 100 0 masked", "if items entity @s weapon.mainhand minecraft:stick",
            f"store result score {_holder(rng)} {_obj(rng)}", f"store success score {_holder(rng)} {_obj(rng)}",
            f"store result storage {_storage(rng)} {_path(rng)} int 1",
            f"store result entity {_single(rng)} Motion[0] double 0.001", "store result bossbar bench:power value",
        )))
    return "execute " + " ".join(parts)


def _command(rng: random.Random) -> str:
    kind = rng.random()
    if kind < 0.50:
        return _scoreboard(rng)
    if kind < 0.80:
        prefix = _execute_prefix(rng)
        if rng.random() < 0.1:  # a chain may end with a condition
            return f"{prefix} if score {_holder(rng)} {_obj(rng)} matches ..{rng.randint(0, 9)}"
        return f"{prefix} run {_scoreboard(rng) if rng.random() < 0.6 else _other(rng)}"
    return _other(rng)


def _scoreboard(rng: random.Random) -> str:
    action = rng.random()
    if action < 0.35:
        return f"scoreboard players operation {_holder(rng)} {_obj(rng)} {rng.choice(OPS)} {_holder(rng)} {_obj(rng)}"
    if action < 0.55:
        return f"scoreboard players set {_holder(rng)} {_obj(rng)} {rng.randint(-2**31, 2**31 - 1)}"
    if action < 0.75:
        return f"scoreboard players {rng.choice(('add', 'remove'))} {_holder(rng)} {_obj(rng)} {rng.randint(0, 5000)}"
    if action < 0.85:
        return f"scoreboard players get {rng.choice(('@s', '#tmp', '$ball'))} {_obj(rng)}"
    if action < 0.90:
        return f"scoreboard players reset {_holder(rng)} {_obj(rng)}"
    if action < 0.95:
        return f"scoreboard objectives add {_obj(rng)} dummy {json.dumps({'text': 'Obj', 'color': 'gold'})}"
    return rng.choice(("scoreboard players enable @a trigger_me", "scoreboard objectives setdisplay sidebar pos_x",
                       "scoreboard objectives modify spin rendertype integer", "scoreboard players list @s"))


def _other(rng: random.Random) -> str:
    return rng.choice((
        f"function {NAMESPACE}:physics/step", f"function #{NAMESPACE}:on_hit",
        f"function {NAMESPACE}:macro/apply {{value:{rng.randint(0, 99)},name:\"ball\"}}",
        f"function {NAMESPACE}:macro/apply with storage {_storage(rng)} args",
        f"return {rng.randint(-10, 10)}", "return fail", f"return run scoreboard players get #tmp {_obj(rng)}",
        f"schedule function {NAMESPACE}:tick {rng.choice(('1t', '20', '2s', '1d'))} "
        f"{rng.choice(('append', 'replace'))}",
        f"schedule clear {NAMESPACE}:tick",
        f"data get {_data_target(rng)} {_path(rng)} 1000", f"data merge storage {_storage(rng)} {{a:1,b:[1,2]}}",
        f"data modify storage {_storage(rng)} {_path(rng)} set value {_snbt(rng)}",
        f"data modify {_data_target(rng)} {_path(rng)} append from {_data_target(rng)} {_path(rng)}",
        f"data modify storage {_storage(rng)} list insert 0 value {_snbt(rng)}",
        f"data modify storage {_storage(rng)} name set string entity @s CustomName 1 -1",
        f"data remove storage {_storage(rng)} {_path(rng)}",
        f"tag {_sel(rng)} {rng.choice(('add', 'remove'))} {rng.choice(TAGS)}", f"tag {_sel(rng)} list",
        f"summon minecraft:marker {_pos(rng)} {{Tags:[\"{rng.choice(TAGS)}\"]}}", "summon armor_stand",
        f"kill {_sel(rng)}", "kill",
        f"tp @s {_pos(rng)}", f"teleport {_sel(rng)} {_single(rng)}", f"tp {_sel(rng)} {_pos(rng)} ~10 ~",
        f"tp @s {_pos(rng)} facing ^ ^ ^1", f"tp @e[tag=ball] ~ ~ ~ facing entity @p feet", "tp 10 64 10",
        f"gamerule maxCommandChainLength {rng.randint(1000, 100000)}", "gamerule doDaylightCycle false",
        f"random value 1..{rng.randint(2, 100)}", f"random roll 0..10 {NAMESPACE}:dice", "random reset * 42 true false",
        "time set day", f"time add {rng.randint(1, 100)}t", "time query gametime",
        f"trigger trigger_me set {rng.randint(0, 9)}", "trigger trigger_me",
        f"say Ball {rng.randint(1, 15)} hit @s",
        f'tellraw @a {{"text":"score: ","extra":[{{"score":{{"name":"@s","objective":"{_obj(rng)}"}}}}]}}',
        'tellraw @a[tag=cue] ["",{"text":"Power","color":"red"}]',
        f"particle minecraft:crit {_pos(rng)} 0 0 0 0 1 force",
        "playsound minecraft:block.note_block.hat master @a ~ ~ ~ 1 2",
        f"setblock {_block_pos(rng)} minecraft:stone", "fill ~-1 ~ ~-1 ~1 ~ ~1 minecraft:air replace minecraft:water",
        'title @a actionbar {"text":"Break!"}', "effect give @s minecraft:speed 1 0 true",
        "bossbar set bench:power value 50", "item replace entity @s weapon.mainhand with minecraft:stick",
        "team join balls @e[tag=ball]", "attribute @s minecraft:generic.scale base set 0.5",
    ))


def _macro_line(rng: random.Random) -> str:
    return rng.choice(("$scoreboard players set #arg tmp $(value)", "$tag @e[name=$(name),limit=1] add selected",
                       "$data modify storage bench:tmp out set value \"$(name)\""))


def _function_lines(rng: random.Random, count: int, macro: bool) -> list[str]:
    lines = [f"# {NAMESPACE}: generated function", "# reads: pos_x pos_y vel_x vel_y; writes: tmp", ""]
    while len(lines) < count:
        roll = rng.random()
        if roll < 0.05:
            lines.append("")
        elif roll < 0.10:
            lines.append(f"# step {len(lines)}")
        elif macro and roll < 0.15:
            lines.append(_macro_line(rng))
        elif roll < 0.17:
            lines.append("execute as @e[tag=ball] at @s \\\n    if score @s state matches 1 \\\n"
                         f"    run function {NAMESPACE}:physics/step")
        else:
            lines.append(("    " if roll > 0.97 else "") + _command(rng))
    return lines


# Resources the generated lines refer to, so the pack also passes cross-reference checks.
FIXED_FUNCTIONS = {
    "load": [f"scoreboard objectives add {name} dummy" for name in OBJECTIVES]
    + ["scoreboard objectives add trigger_me trigger"],
    "physics/step": ["# one integration step (kept tiny: generated functions call it a lot)",
                     "scoreboard players operation @s pos_x += @s vel_x",
                     "scoreboard players operation @s pos_y += @s vel_y"],
    "tick": ["scoreboard players add #ticks timer 1"],
    "util/check": ["execute if score #tmp state matches 1.. run return 1", "return 0"],
    "macro/apply": ["$scoreboard players set #arg tmp $(value)", "$tag @e[name=$(name),limit=1] add selected"],
}
FUNCTION_TAGS = {"on_hit": [f"{NAMESPACE}:physics/step"]}
PREDICATES = {"is_moving": {"condition": "minecraft:entity_properties", "entity": "this",
                            "predicate": {"flags": {"is_on_ground": False}}}}


def _write(path: Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)


def write_corpus(dest_dir, lines: int = 40000, seed: int = 0) -> int:
    """Write the pack under ``dest_dir``; returns the number of function lines written."""
    rng = random.Random(seed)
    root = Path(dest_dir)
    data = root / "data" / NAMESPACE
    _write(root / "pack.mcmeta", json.dumps({"pack": {"pack_format": PACK_FORMAT, "description": "parser benchmark"}}))
    for name, values in FUNCTION_TAGS.items():
        _write(data / "tags" / "function" / f"{name}.json", json.dumps({"values": values}))
    load_tag = root / "data" / "minecraft" / "tags" / "function" / "load.json"
    _write(load_tag, json.dumps({"values": [f"{NAMESPACE}:load"]}))
    for name, predicate in PREDICATES.items():
        _write(data / "predicate" / f"{name}.json", json.dumps(predicate))
    written = 0
    for name, body in FIXED_FUNCTIONS.items():
        text = "\n".join(body) + "\n"
        _write(data / "function" / f"{name}.mcfunction", text)
        written += len(body)
    index = 0
    while written < lines:
        folder = ("physics", "util", "macro", "ui", "balls")[index % 5]
        count = min(rng.randint(20, 120), max(lines - written, 5))
        text = "\n".join(_function_lines(rng, count, macro=(folder == "macro"))) + "\n"
        _write(data / "function" / folder / f"f{index:04d}.mcfunction", text)
        written += text.count("\n")
        index += 1
    return written


if __name__ == "__main__":
    print(write_corpus(sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 40000), "lines written")
