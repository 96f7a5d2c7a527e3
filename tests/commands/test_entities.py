"""Entity commands parsed by the project's parser and run by :mod:`emulator.commands`.

Sources (decompiled 1.21): server/commands/TeleportCommand.java, SummonCommand.java,
commands/arguments/EntityArgument.java, java.util.UUID.fromString.
"""
from __future__ import annotations

import numpy as np
import pytest

from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.parse import parse_command
from dataclasses import replace

from emulator.commands.dispatch import run_command
from emulator.commands.entities import entity_context, new_state, parse_uuid, single
from emulator.commands.env import Env
from emulator.world.errors import CommandFailure
from emulator.world import rotation
from emulator.world.context import Context

F32 = np.float32


def parsed(text: str):
    cmd, diagnostics = parse_command(text, Loc("t.mcfunction", 1, 1), (1, 21, 0))
    assert not diagnostics, diagnostics
    return cmd


def test_parse_uuid_is_javas_from_string():
    assert parse_uuid("00000001-0000-0002-0000-000300000004") == (1, 2, 3, 4)
    assert parse_uuid("1-2-3-4-5") == (1, 0x20003, 0x40000, 5)  # short groups are allowed


def run(env: Env, text: str, ctx: Context | None = None) -> int:
    return run_command(env, parsed(text), ctx or Context())


def summoned(env: Env, text: str, ctx: Context):
    run(env, text, ctx)
    return env.state.entities.entities[-1]


def test_summon_then_teleport_forms():
    env = Env(new_state(), {}, set())
    here = Context(pos=(10.0, 64.0, 10.0))
    ball = summoned(env, 'summon marker ~ ~ ~ {Tags:["ball"],Rotation:[370f,0f]}', here)
    assert ball.pos == (10.0, 64.0, 10.0) and ball.yaw == F32(10.0)
    cue = summoned(env, "summon armor_stand 0 64 0", here)
    assert cue.pos == (0.5, 64.0, 0.5)  # integer x/z are centred
    assert run(env, "tp @s ^ ^ ^1", entity_context(env.state, ball)) == 1
    assert ball.pos == pytest.approx((10.0 - float(np.sin(np.radians(10.0))), 64.0, 10.0 + float(np.cos(np.radians(10.0)))), abs=1e-4)
    run(env, "tp @e[tag=ball] ~ ~1 ~ facing entity @e[type=armor_stand,limit=1] eyes", here)
    assert ball.pos == (10.0, 65.0, 10.0)
    assert (ball.yaw, ball.pitch) == rotation.facing_rotation(ball.pos, cue.anchor("eyes"))
    assert run(env, "tp @e[tag=ball] @e[type=armor_stand,limit=1]", here) == 1
    assert ball.pos == cue.pos
    run(env, "tp 1 2 3", replace(entity_context(env.state, ball), rot=(45.0, 0.0)))
    assert ball.pos == (1.5, 2.0, 3.5) and ball.yaw == F32(45.0)


def test_entity_arguments_fail_like_the_game():
    env = Env(new_state(), {}, set())
    store = env.state.entities
    store.summon("minecraft:marker", (0, 0, 0))
    store.summon("minecraft:marker", (0, 0, 0))
    with pytest.raises(CommandFailure, match="No entity was found"):
        run(env, "tp @e[tag=none] ~ ~ ~")
    with pytest.raises(CommandFailure, match="An entity is required"):
        run(env, "tp 0 0 0")
    steve = store.add_player("Steve", (5, 5, 5))
    assert single(env.state, parsed("tp Steve ~ ~ ~").targets, Context()) is steve
    uuid_text = store.entities[0].uuid_string
    assert single(env.state, parsed(f"tp {uuid_text} ~ ~ ~").targets, Context()) is store.entities[0]


def test_kill_and_tag_commands():
    env = Env(new_state(), {}, set())
    store = env.state.entities
    a = store.summon("minecraft:marker", (0, 0, 0))
    b = store.summon("minecraft:marker", (0, 0, 0))
    steve = store.add_player("Steve", (0, 0, 0))
    as_a = entity_context(env.state, a)
    assert run(env, "tag @e add ball", as_a) == 3
    with pytest.raises(CommandFailure, match="already has the tag"):
        run(env, "tag @e add ball", as_a)
    assert run(env, "tag @s remove ball", as_a) == 1
    with pytest.raises(CommandFailure, match="does not have this tag"):
        run(env, "tag @s remove ball", as_a)
    assert run(env, "tag @e list", as_a) == 1
    assert run(env, "kill @e[tag=ball]", as_a) == 2  # b and Steve
    assert store.entities == [a, steve] and not b.alive
    assert run(env, "kill", as_a) == 1
    assert store.entities == [steve]


@pytest.mark.parametrize("nbt,reported", [
    ("", True),  # llama spit falls with gravity from rest
    ("{NoGravity:1b}", False),  # no gravity, no motion: it stays
    ("{NoGravity:1b,Motion:[0.0,0.0,0.5]}", True),
])
def test_a_summoned_projectile_the_emulator_does_not_move_is_reported_in_flight(tmp_path, nbt, reported):
    # LlamaSpit.tick moves the spit every tick (motion, gravity, drag, hits): it is not moved here
    # (arrows, snowballs and thrown items are: test_projectile_flight, test_thrown_hits)
    from emulator import Emulator
    from tests.conftest import write_pack
    emu = Emulator(backend="python")
    emu.load([write_pack(tmp_path / "p", {"demo/function/f.mcfunction": f"summon llama_spit 0 0 0 {nbt}\n"})])
    emu.call("demo:f")
    assert not any(d.unmodelled for d in emu.diagnostics)  # not yet: it has not moved in the game either
    emu.tick()
    assert any(d.unmodelled and "projectiles do not move" in d.message for d in emu.diagnostics) == reported
