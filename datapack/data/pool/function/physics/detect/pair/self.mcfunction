# pool:physics/detect/pair/self — @s becomes the first ball of the pair tests (tag pool.self): its
# pool.id and chord box into #a.*. Writes: tag pool.self, #a.id #a.lx #a.hx #a.lz #a.hz pool.tmp.
tag @s add pool.self
scoreboard players operation #a.id pool.tmp = @s pool.id
scoreboard players operation #a.lx pool.tmp = @s pool.lx
scoreboard players operation #a.hx pool.tmp = @s pool.hx
scoreboard players operation #a.lz pool.tmp = @s pool.lz
scoreboard players operation #a.hz pool.tmp = @s pool.hz
