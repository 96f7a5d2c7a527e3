# pool:physics/detect/sweep/unit_memo — the remembered result of pool:physics/detect/sweep/unit.
# Reads: #sweep.unit.ux #sweep.unit.uz #sweep.unit.len pool.tmp. Writes: $ux $uz $len pool.math.
scoreboard players operation $ux pool.math = #sweep.unit.ux pool.tmp
scoreboard players operation $uz pool.math = #sweep.unit.uz pool.tmp
scoreboard players operation $len pool.math = #sweep.unit.len pool.tmp
