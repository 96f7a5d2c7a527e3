"""``advancement grant|revoke`` and what reads progress (AdvancementCommands, PlayerAdvancements,
EntitySelectorOptions ``advancements``; decompiled 1.21): the failure messages, the counts, the
targets, and progress that waits on a trigger the emulator does not observe."""
import json

import pytest

from emulator import Emulator
from emulator.commands.dispatch import run_command
from emulator.commands.env import Env
from emulator.world.context import Context
from emulator.world.errors import CommandFailure, Unmodelled
from mcfunction_parser.diagnostics import Loc
from mcfunction_parser.parse import parse_command
from tests.world.world_emulator import make_pack

ADVANCEMENTS = {
    "a/one": {"criteria": {"x": {"trigger": "minecraft:impossible"}}},
    "a/two": {"criteria": {"x": {"trigger": "minecraft:impossible"}}, "parent": "t:a/one"},
    "a/held": {"criteria": {"got": {"trigger": "minecraft:bred_animals"}}},
}


@pytest.fixture
def emu(tmp_path):
    root = make_pack(tmp_path / "p", {"t:setup": "scoreboard objectives add o dummy"})
    for path, body in ADVANCEMENTS.items():
        file = root / "data" / "t" / "advancement" / f"{path}.json"
        file.parent.mkdir(parents=True, exist_ok=True)
        file.write_text(json.dumps(body))
    emu = Emulator(backend="python")
    emu.load(root)
    emu.call("t:setup")
    emu.add_player("Alex", (0, 0, 0))
    emu.add_player("Steve", (0, 0, 0))
    return emu


def run(emu, command):
    """The command run alone as the server: (its result, None) or (0, the failure's message)."""
    cmd, problems = parse_command(command, Loc("t", 1, 1), (1, 21, 0))
    assert not problems
    try:
        return run_command(Env(emu.state, emu.packs.functions, emu.packs.tags), cmd, Context()), None
    except CommandFailure as failure:
        return 0, failure.message


def test_counts_and_failure_messages(emu):
    # AdvancementCommands.perform: the (player, advancement) pairs changed; none fails
    assert run(emu, "advancement grant @a until t:a/two") == (4, None)
    assert run(emu, "advancement grant Alex only t:a/one") == (
        0, "Couldn't grant advancement [t:a/one] to Alex as they already have it")
    assert run(emu, "advancement grant @a only t:a/one") == (
        0, "Couldn't grant advancement [t:a/one] to 2 players as they already have it")
    assert run(emu, "advancement revoke Alex from t:a/one") == (2, None)
    assert run(emu, "advancement revoke Alex from t:a/one") == (
        0, "Couldn't revoke 2 advancements from Alex as they don't have them")
    assert run(emu, "advancement grant Alex only t:a/one y") == (
        0, "The advancement [t:a/one] does not contain the criterion 'y'")
    assert run(emu, "advancement grant Alex only t:nope") == (0, "Unknown advancement: t:nope")
    assert run(emu, "advancement grant Nobody everything") == (0, "No player was found")


def test_progress_waiting_on_an_unobserved_trigger_is_not_read_silently(emu):
    with pytest.raises(Unmodelled, match="bred_animals, which the emulator does not observe"):
        emu.entities("@a[advancements={t:a/held=false}]")
    run(emu, "advancement grant @a only t:a/held")
    assert len(emu.entities("@a[advancements={t:a/held=true}]")) == 2  # granted: known again
