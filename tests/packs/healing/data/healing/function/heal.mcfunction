# Heals the executing player fully: instant health 28 heals 4 << 28; the reward fires when the
# effect is gone, after it acted in the player's tick.
execute if predicate {condition: "entity_properties", entity: "this", predicate: {effects: {"minecraft:instant_health": {amplifier: {min: 29}}}}} run effect clear @s minecraft:instant_health
effect give @s minecraft:instant_health 1 28 true
advancement revoke @s only healing:on_heal
