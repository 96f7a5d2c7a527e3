"""The world's weak containers (what the game keeps on its entities without saving it): their
truth test, asked by the tick's steps every tick, follows their entries without ``__len__``."""
import gc

from emulator.world.state import WeakKeys, WeakMembers, WorldState


class _Held:
    pass


def test_a_weak_container_is_true_while_an_entry_lives():
    for container, add in ((WeakKeys(), lambda c, k: c.__setitem__(k, 1)), (WeakMembers(), WeakMembers.add)):
        assert not container and len(container) == 0
        held = _Held()
        add(container, held)
        assert container and len(container) == 1
        del held
        gc.collect()
        assert not container and len(container) == 0


def test_the_world_keeps_its_unsaved_entity_state_in_them():
    state = WorldState()
    assert isinstance(state.open_menus, WeakKeys) and isinstance(state.hurt_timers, WeakKeys)
    assert isinstance(state.dead_players, WeakMembers)
