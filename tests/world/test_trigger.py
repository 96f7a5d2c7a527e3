"""Trigger locks: Scoreboard.locked and the ``enable``/``trigger`` rules.

Source: decompiled 1.21 world/scores/Score.java (``locked = true`` for every new score),
server/commands/TriggerCommand.java (getScore: the score must exist and be unlocked; it is
locked again on use), server/commands/ScoreboardCommand.java (enableTrigger: get-or-create, unlock).
"""
import numpy as np

from emulator.world.state import Scoreboard


def test_locked_array_has_the_shape_and_growth_of_present():
    sb = Scoreboard()
    assert sb.locked.dtype == np.uint8 and sb.locked.shape == sb.present.shape
    for i in range(200):  # past the initial capacity on both axes
        sb.set(f"h{i}", f"o{i % 40}", i)
    assert sb.locked.shape == sb.present.shape
    assert sb.locked.all()  # a new score is locked (Score.locked = true)


def test_enable_creates_and_unlocks_reset_locks_again():
    sb = Scoreboard()
    sb.add_objective("t", "trigger")
    assert not sb.is_unlocked("p", "t")
    sb.enable("p", "t")
    assert sb.get("p", "t") == 0 and sb.is_unlocked("p", "t")
    sb.reset("p", "t")  # the Score object is dropped; a new one starts locked
    sb.set("p", "t", 5)
    assert not sb.is_unlocked("p", "t")


def test_enable_keeps_an_existing_value_and_lock_relocks():
    sb = Scoreboard()
    sb.add_objective("t", "trigger")
    sb.set("p", "t", 7)
    sb.enable("p", "t")
    assert sb.get("p", "t") == 7 and sb.is_unlocked("p", "t")
    sb.lock("p", "t")
    assert not sb.is_unlocked("p", "t")


def test_removing_the_objective_locks_its_column():
    sb = Scoreboard()
    sb.add_objective("t", "trigger")
    sb.enable("p", "t")
    sb.remove_objective("t")
    sb.add_objective("t", "trigger")
    sb.set("p", "t", 1)
    assert not sb.is_unlocked("p", "t")
