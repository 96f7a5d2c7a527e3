# pool:physics/find/separating — for a contact the sweep puts at the sub-step's start: returns 1
# when b (@s) and a (tagged pool.self) move apart there, (v_b - v_a) . (r_b - r_a) >= 0, with the
# velocities saved at their chords' starts. Their chords can still converge (a sliding ball's
# path curves away from its chord); such a pair is no event: resolving it changes nothing and
# would find it again at the same time for ever.
# Reads: #dx #dz pool.tmp (r_b - r_a at #now, from the sweep), @s and pool.self's pool.bvx pool.bvz.
# Writes: #sx #sz pool.tmp.
scoreboard players operation #sx pool.tmp = @s pool.bvx
execute as @e[tag=pool.self] run scoreboard players operation #sx pool.tmp -= @s pool.bvx
scoreboard players operation #sz pool.tmp = @s pool.bvz
execute as @e[tag=pool.self] run scoreboard players operation #sz pool.tmp -= @s pool.bvz
# |r_b - r_a| is about 2R here: in mm it keeps the products below 2^31 at any speed
scoreboard players operation #dx pool.tmp /= #1000 pool.const
scoreboard players operation #dz pool.tmp /= #1000 pool.const
scoreboard players operation #sx pool.tmp *= #dx pool.tmp
scoreboard players operation #sz pool.tmp *= #dz pool.tmp
scoreboard players operation #sx pool.tmp += #sz pool.tmp
execute if score #sx pool.tmp matches 0.. run return 1
return 0
