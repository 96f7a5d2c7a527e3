# pool:physics/motion/slide/fine — split a fine quantity #slide.p (1/2000 um or um/tick) into whole
# units and what is left: #slide.q = round(#slide.p / 2000), halves away from zero (mirror-
# symmetric), and #slide.p -= 2000 #slide.q (|#slide.p| <= 1000 after).
# Reads/writes: #slide.p pool.tmp (|p| < 2^31 - 1000). Writes: #slide.q #slide.r pool.tmp.
scoreboard players operation #slide.q pool.tmp = #slide.p pool.tmp
execute if score #slide.p pool.tmp matches ..-1 run scoreboard players operation #slide.q pool.tmp *= #-1 pool.const
scoreboard players add #slide.q pool.tmp 1000
scoreboard players operation #slide.q pool.tmp /= #2000 pool.const
execute if score #slide.p pool.tmp matches ..-1 run scoreboard players operation #slide.q pool.tmp *= #-1 pool.const
scoreboard players operation #slide.r pool.tmp = #slide.q pool.tmp
scoreboard players operation #slide.r pool.tmp *= #2000 pool.const
scoreboard players operation #slide.p pool.tmp -= #slide.r pool.tmp
