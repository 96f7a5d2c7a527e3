# pool:physics/detect/absolute — #detect.t = the tick time of fraction #sweep.f of the interval
# #events.now..10000.
# Reads: #sweep.f #events.now #events.rem pool.tmp (f, rem <= 10000). Writes: #detect.t pool.tmp.
scoreboard players operation #detect.t pool.tmp = #sweep.f pool.tmp
scoreboard players operation #detect.t pool.tmp *= #events.rem pool.tmp
scoreboard players operation #detect.t pool.tmp /= #10000 pool.const
scoreboard players operation #detect.t pool.tmp += #events.now pool.tmp
