"""Entity commands parsed by the project's parser and run on the world library.

Sources (decompiled 1.21): server/commands/TeleportCommand.java, SummonCommand.java,
commands/arguments/EntityArgument.java, java.util.UUID.fromString.
"""
from __future__ import annotations

import numpy as np
import pytest

from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.parse import parse_command
from emulator.world import rotation
from emulator.world.commands import parse_uuid, resolve_entity, summon_command, teleport_command
from emulator.world.entities import EntityStore
from emulator.world.errors import CommandFailure
from emulator.world.source import Source

F32 = np.float32


def parsed(text: str):
    cmd, diagnostics = parse_command(text, Loc("t.mcfunction", 1, 1), (1, 21, 0))
    assert not diagnostics, diagnostics
    return cmd


def test_parse_uuid_is_javas_from_string():
    assert parse_uuid("00000001-0000-0002-0000-000300000004") == (1, 2, 3, 4)
    assert parse_uuid("1-2-3-4-5") == (1, 0x20003, 0x40000, 5)  # short groups are allowed


def test_summon_then_teleport_forms():
    store = EntityStore(1)
    src = Source(pos=(10.0, 64.0, 10.0))
    ball = summon_command(parsed('summon marker ~ ~ ~ {Tags:["ball"],Rotation:[370f,0f]}'), store, src)
    assert ball.pos == (10.0, 64.0, 10.0) and ball.yaw == F32(10.0)
    cue = summon_command(parsed("summon armor_stand 0 64 0"), store, src)
    assert cue.pos == (0.5, 64.0, 0.5)  # integer x/z are centred
    at_ball = Source(entity=ball).at(ball)
    assert teleport_command(parsed("tp @s ^ ^ ^1"), store, at_ball) == 1
    assert ball.pos == pytest.approx((10.0 - float(np.sin(np.radians(10.0))), 64.0, 10.0 + float(np.cos(np.radians(10.0)))), abs=1e-4)
    teleport_command(parsed("tp @e[tag=ball] ~ ~1 ~ facing entity @e[type=armor_stand,limit=1] eyes"), store, src)
    assert ball.pos == (10.0, 65.0, 10.0)
    assert (ball.yaw, ball.pitch) == rotation.facing_rotation(ball.pos, cue.anchor("eyes"))
    assert teleport_command(parsed("tp @e[tag=ball] @e[type=armor_stand,limit=1]"), store, src) == 1
    assert ball.pos == cue.pos
    teleport_command(parsed("tp 1 2 3"), store, Source(entity=ball, yaw=F32(45.0)))
    assert ball.pos == (1.5, 2.0, 3.5) and ball.yaw == F32(45.0)


def test_entity_arguments_fail_like_the_game():
    store = EntityStore()
    store.summon("minecraft:marker", (0, 0, 0))
    store.summon("minecraft:marker", (0, 0, 0))
    with pytest.raises(CommandFailure, match="No entity was found"):
        teleport_command(parsed("tp @e[tag=none] ~ ~ ~"), store, Source())
    with pytest.raises(CommandFailure, match="An entity is required"):
        teleport_command(parsed("tp 0 0 0"), store, Source())
    steve = store.add_player("Steve", (5, 5, 5))
    assert resolve_entity(parsed("tp Steve ~ ~ ~").targets, store, Source()) is steve
    uuid_text = store.entities[0].uuid_string
    assert resolve_entity(parsed(f"tp {uuid_text} ~ ~ ~").targets, store, Source()) is store.entities[0]


def test_kill_and_tag_commands():
    from emulator.world.commands import kill_command, tag_command

    store = EntityStore()
    a = store.summon("minecraft:marker", (0, 0, 0))
    b = store.summon("minecraft:marker", (0, 0, 0))
    steve = store.add_player("Steve", (0, 0, 0))
    src = Source(entity=a)
    assert tag_command(parsed("tag @e add ball"), store, src) == 3
    with pytest.raises(CommandFailure, match="already has the tag"):
        tag_command(parsed("tag @e add ball"), store, src)
    assert tag_command(parsed("tag @s remove ball"), store, src) == 1
    with pytest.raises(CommandFailure, match="does not have this tag"):
        tag_command(parsed("tag @s remove ball"), store, src)
    assert tag_command(parsed("tag @e list"), store, src) == 1
    assert kill_command(parsed("kill @e[tag=ball]"), store, src) == 2  # b and Steve
    assert store.entities == [a, steve] and not b.alive
    assert kill_command(parsed("kill"), store, src) == 1
    assert store.entities == [steve]
