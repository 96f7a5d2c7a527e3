# pool:physics/resolve/separate/pushed — start a pass over the balls that the last pass pushed: they
# are tagged pool.again (pool:physics/resolve/separate/passes goes through them).
# Writes: tags pool.again, pool.shifted (removed); #separate.passes pool.tmp.
tag @e[tag=pool.shifted,scores={pool.state=0..2}] add pool.again
tag @e[tag=pool.shifted] remove pool.shifted
scoreboard players add #separate.passes pool.tmp 1
