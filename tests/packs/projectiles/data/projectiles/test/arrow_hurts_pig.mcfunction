# @skyaccess
# An arrow dropped onto a pig hurts it by ceil(speed x 2) and is gone (the pig resists knockback:
# an arrow falling straight down would push it in a random direction)
summon pig ~0.5 ~ ~0.5 {NoAI:1b,NoGravity:1b,Tags:["target"],attributes:[{id:"minecraft:generic.knockback_resistance",base:1.0d}]}
summon arrow ~0.5 ~1.5 ~0.5 {Motion:[0.0d,-1.0d,0.0d],Tags:["shot"]}
await not entity @e[tag=shot]
assert entity @e[tag=target,nbt={Health:8.0f}]
