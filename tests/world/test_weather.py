"""Weather.advance_ticks (the VM's batches of ticks) ends where as many ticks of
ServerLevel.advanceWeatherCycle one by one end: the timers, the flags, the float32 levels and the
stand-in random's draws alike."""
from __future__ import annotations

import copy

from hypothesis import given, settings
from hypothesis import strategies as st

from emulator.world.weather import Weather


def _fields(weather: Weather) -> tuple:
    return (weather.clear_time, weather.rain_time, weather.thunder_time, weather.raining, weather.thundering,
            float(weather.rain_level), float(weather.thunder_level), weather.random.getstate())


@settings(max_examples=200, deadline=None)
@given(clear=st.integers(0, 300), rain=st.integers(0, 300), thunder=st.integers(0, 300), raining=st.booleans(),
       thundering=st.booleans(), rain_level=st.sampled_from([0.0, 1.0, 0.5]), cycle=st.booleans(),
       steps=st.lists(st.integers(0, 400), min_size=1, max_size=4))
def test_advancing_at_once_equals_tick_by_tick(clear, rain, thunder, raining, thundering, rain_level, cycle, steps):
    one = Weather(clear_time=clear, rain_time=rain, thunder_time=thunder, raining=raining, thundering=thundering)
    one.rain_level = one.thunder_level = type(one.rain_level)(rain_level)
    many = copy.deepcopy(one)
    for n in steps:
        for _ in range(n):
            one._step(cycle)  # ServerLevel.advanceWeatherCycle as written, one tick
        many.advance_ticks(n, cycle)
        assert _fields(many) == _fields(one)


def test_one_tick_at_a_time_is_the_same():
    one, other = Weather(clear_time=3, rain_time=1, thunder_time=1), Weather(clear_time=3, rain_time=1, thunder_time=1)
    for _ in range(500):
        one.advance(True)
        other._step(True)
        assert _fields(one) == _fields(other)


def test_a_long_quiet_stretch_is_counted_down_at_once():
    weather = Weather(rain_time=100_000, thunder_time=90_000)
    weather.advance_ticks(50_000, True)
    assert (weather.rain_time, weather.thunder_time, weather.raining) == (50_000, 40_000, False)
