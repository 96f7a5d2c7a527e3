# @dummy
# MinMaxBounds.Ints read by Codec.INT: a bound written 4.8 is 4 (Number.intValue truncates)
xp set @s 4 levels
assert entity @s[predicate=gated:seasoned]
xp set @s 3 levels
assert not entity @s[predicate=gated:seasoned]
item replace entity @s weapon.mainhand with minecraft:stick 2
assert items entity @s weapon.mainhand *[count={min:2.9,max:2.1}]
assert not items entity @s weapon.mainhand *[count={min:3.0}]
