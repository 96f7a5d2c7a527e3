setblock ~ ~ ~ water
assert predicate gated:in_water
execute positioned ~1 ~ ~ run assert not predicate gated:in_water
time set 14000
assert predicate gated:night
time set 1000
assert not predicate gated:night
