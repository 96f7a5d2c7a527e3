# pool:api/shot/apply — validate the shot in #api.* pool.tmp and strike the cue ball.
# Reads: #api.angle #api.speed #api.tip_x #api.tip_y #api.elevation pool.tmp, $resting pool.game.
# Writes: $shot.* and $resting pool.game, the cue ball's scores; or a refusal message and nothing.
scoreboard players set #api.ok pool.tmp 1
execute if score $resting pool.game matches 0 run function pool:api/shot/refuse {reason:"the balls are still moving"}
execute unless entity @e[tag=pool.ball,scores={pool.id=0,pool.state=0..2}] run function pool:api/shot/refuse {reason:"the cue ball is not on the table (function pool:table/spot_cue)"}
execute unless score #api.speed pool.tmp matches 1..6500 run function pool:api/shot/refuse {reason:"speed must be 1..6500 (mm/s)"}
execute unless score #api.elevation pool.tmp matches 0..8900 run function pool:api/shot/refuse {reason:"elevation must be 0..8900 (centidegrees)"}
execute unless score #api.tip_x pool.tmp matches -500..500 run function pool:api/shot/refuse {reason:"tip_x must be -500..500"}
execute unless score #api.tip_y pool.tmp matches -500..500 run function pool:api/shot/refuse {reason:"tip_y must be -500..500"}
execute if score #api.ok pool.tmp matches 0 run return fail
scoreboard players operation #api.t pool.tmp = #api.tip_x pool.tmp
scoreboard players operation #api.t pool.tmp *= #api.tip_x pool.tmp
scoreboard players operation #api.d pool.tmp = #api.tip_y pool.tmp
scoreboard players operation #api.d pool.tmp *= #api.tip_y pool.tmp
scoreboard players operation #api.t pool.tmp += #api.d pool.tmp
execute unless score #api.t pool.tmp matches ..250000 run function pool:api/shot/refuse {reason:"the tip offset is past the miscue limit (tip_x^2 + tip_y^2 <= 250000)"}
execute if score #api.ok pool.tmp matches 0 run return fail
scoreboard players operation $shot.angle pool.game = #api.angle pool.tmp
scoreboard players operation $shot.speed pool.game = #api.speed pool.tmp
scoreboard players operation $shot.tip_x pool.game = #api.tip_x pool.tmp
scoreboard players operation $shot.tip_y pool.game = #api.tip_y pool.tmp
scoreboard players operation $shot.elevation pool.game = #api.elevation pool.tmp
execute as @e[tag=pool.ball,scores={pool.id=0,pool.state=0..2},limit=1] run function pool:cue/strike
tag @e[tag=pool.ball] remove pool.settled
scoreboard players set $resting pool.game 0
return 1
