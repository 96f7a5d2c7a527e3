summon zombie ~1 ~ ~1 {Tags:["marked"],NoAI:1b}
summon zombie ~1 ~ ~1 {Tags:["plain"],NoAI:1b}
summon pig ~1 ~ ~1 {Tags:["marked"],NoAI:1b}
await delay 3
assert score @e[tag=marked,type=zombie,limit=1] gated.ticks matches 3
assert not entity @e[tag=plain,scores={gated.ticks=0..}]
assert not entity @e[type=pig,scores={gated.ticks=0..}]
