# pool:physics/detect/absolute — #t = the tick time of fraction #f of the interval #now..10000.
# Reads: #f #now #rem pool.tmp (f, rem <= 10000). Writes: #t pool.tmp.
scoreboard players operation #t pool.tmp = #f pool.tmp
scoreboard players operation #t pool.tmp *= #rem pool.tmp
scoreboard players operation #t pool.tmp /= #10000 pool.const
scoreboard players operation #t pool.tmp += #now pool.tmp
