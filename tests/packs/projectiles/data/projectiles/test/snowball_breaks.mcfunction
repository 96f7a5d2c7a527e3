# A snowball thrown at the wall breaks on it
summon snowball ~0.5 ~0.5 ~0.5 {Motion:[0.4d,0.0d,0.0d],Tags:["ball"]}
await delay 1
assert entity @e[tag=ball]
await not entity @e[tag=ball]
