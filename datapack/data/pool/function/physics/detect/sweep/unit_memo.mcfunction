# pool:physics/detect/sweep/unit_memo — the remembered result of pool:physics/detect/sweep/unit.
# Reads: #unit.ux #unit.uz #unit.len pool.tmp. Writes: $ux $uz $len pool.math.
scoreboard players operation $ux pool.math = #unit.ux pool.tmp
scoreboard players operation $uz pool.math = #unit.uz pool.tmp
scoreboard players operation $len pool.math = #unit.len pool.tmp
