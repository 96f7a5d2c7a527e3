# pool:physics/detect/pair/offer — the contact of ball @s (which keeps its chord) with the ball
# tagged pool.self (a new chord) becomes @s's stored event if it is earlier than the one @s has.
# Reads: @s pool.nt, #pair.a.id pool.tmp. Writes: @s pool.nt pool.nk pool.np; through
# pool:physics/detect/pair/contact.
execute unless function pool:physics/detect/pair/contact run return 0
execute if score #detect.t pool.tmp >= @s pool.nt run return 0
scoreboard players operation @s pool.nt = #detect.t pool.tmp
scoreboard players set @s pool.nk 1
scoreboard players operation @s pool.np = #pair.a.id pool.tmp
