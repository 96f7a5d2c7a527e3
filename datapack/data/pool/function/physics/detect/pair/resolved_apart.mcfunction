# pool:physics/detect/pair/resolved_apart — returns 1 when a (#a.id) and b (@s) are the pair whose
# resolution at #now found them not approaching (pool:physics/resolve/ball_ball/no_hit), else 0.
# Reads: #a.id #now #nohit.a #nohit.b #nohit.t pool.tmp, @s pool.id.
execute unless score #nohit.t pool.tmp = #now pool.tmp run return 0
execute if score #a.id pool.tmp = #nohit.a pool.tmp if score @s pool.id = #nohit.b pool.tmp run return 1
execute if score #a.id pool.tmp = #nohit.b pool.tmp if score @s pool.id = #nohit.a pool.tmp run return 1
return 0
