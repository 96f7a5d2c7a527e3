# pool:physics/find/store — keep the earliest event found for @s.
# Reads: #best #kind #event_rail #partner pool.tmp. Writes: @s pool.nt pool.nk pool.nr pool.np.
scoreboard players operation @s pool.nt = #best pool.tmp
scoreboard players operation @s pool.nk = #kind pool.tmp
scoreboard players operation @s pool.nr = #event_rail pool.tmp
scoreboard players operation @s pool.np = #partner pool.tmp
