"""``dpemu run --player/--shuffle`` and the entities in ``--json``."""
from __future__ import annotations

import json

from click.testing import CliRunner

from emulator.cli import main
from tests.backends.programs import write_pack

TICK = ("execute as @a at @s run summon marker ^ ^ ^1 {Tags:[\"m\"]}\n"
        "execute as @e[type=marker] run scoreboard players add @s n 1\n")


def run(tmp_path, *options) -> dict:
    pack = write_pack(tmp_path / "pack", {"t:load": "scoreboard objectives add n dummy", "t:tick": TICK},
                      {"minecraft:load": ["t:load"], "minecraft:tick": ["t:tick"]})
    result = CliRunner().invoke(main, ["run", str(pack), "--ticks", "3", "--json", "-", *options])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def test_players_and_entities_in_json(tmp_path):
    report = run(tmp_path, "--player", "Alex@0.5,64,0.5,90,0", "--backend", "python")
    players = [e for e in report["entities"] if e["type"] == "minecraft:player"]
    markers = [e for e in report["entities"] if e["type"] == "minecraft:marker"]
    assert [(p["name"], p["pos"], p["rotation"]) for p in players] == [("Alex", [0.5, 64.0, 0.5], [90.0, 0.0])]
    assert [m["scores"] for m in markers] == [{"n": 3}, {"n": 2}, {"n": 1}]  # creation order
    assert all(m["pos"][0] < 0 for m in markers)  # yaw 90 looks towards -x


def test_shuffle_changes_the_order_not_the_outcome(tmp_path):
    plain = run(tmp_path / "a", "--player", "Alex@0,64,0")
    shuffled = run(tmp_path / "b", "--player", "Alex@0,64,0", "--shuffle", "5")
    assert sorted(map(json.dumps, plain["entities"])) == sorted(map(json.dumps, shuffled["entities"]))
    assert plain["entities"] != shuffled["entities"]


def test_bad_player_is_a_usage_error(tmp_path):
    pack = write_pack(tmp_path / "pack", {"t:f": "say hi"})
    result = CliRunner().invoke(main, ["run", str(pack), "--player", "Alex@1,2"])
    assert result.exit_code == 2 and "NAME@X,Y,Z" in result.output
