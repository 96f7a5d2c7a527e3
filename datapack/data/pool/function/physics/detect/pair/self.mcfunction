# pool:physics/detect/pair/self — @s becomes the first ball of the pair tests (tag pool.self): its
# pool.id and chord box into #pair.a.*. Writes: tag pool.self, #pair.a.id #pair.a.lx #pair.a.hx
# #pair.a.lz #pair.a.hz pool.tmp.
tag @s add pool.self
scoreboard players operation #pair.a.id pool.tmp = @s pool.id
scoreboard players operation #pair.a.lx pool.tmp = @s pool.lx
scoreboard players operation #pair.a.hx pool.tmp = @s pool.hx
scoreboard players operation #pair.a.lz pool.tmp = @s pool.lz
scoreboard players operation #pair.a.hz pool.tmp = @s pool.hz
