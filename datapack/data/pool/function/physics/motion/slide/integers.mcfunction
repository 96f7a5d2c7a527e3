# pool:physics/motion/slide/integers — the integer state of the sliding @s from its fine state
# (pool:physics/motion/slide/advance): the position's whole um move from pool.px pool.pz into
# pool.x pool.z (what is left, at most half a um, stays), the velocity and spin rounded to um/tick.
# Reads/writes: @s pool.px pool.pz pool.x pool.z. Reads @s pool.fvx pool.fvz pool.fwx pool.fwz.
# Writes: @s pool.vx pool.vz pool.wx pool.wz; through pool:physics/motion/slide/fine.
scoreboard players operation #slide.p pool.tmp = @s pool.px
function pool:physics/motion/slide/fine
scoreboard players operation @s pool.x += #slide.q pool.tmp
scoreboard players operation @s pool.px = #slide.p pool.tmp
scoreboard players operation #slide.p pool.tmp = @s pool.pz
function pool:physics/motion/slide/fine
scoreboard players operation @s pool.z += #slide.q pool.tmp
scoreboard players operation @s pool.pz = #slide.p pool.tmp
scoreboard players operation #slide.p pool.tmp = @s pool.fvx
function pool:physics/motion/slide/fine
scoreboard players operation @s pool.vx = #slide.q pool.tmp
scoreboard players operation #slide.p pool.tmp = @s pool.fvz
function pool:physics/motion/slide/fine
scoreboard players operation @s pool.vz = #slide.q pool.tmp
scoreboard players operation #slide.p pool.tmp = @s pool.fwx
function pool:physics/motion/slide/fine
scoreboard players operation @s pool.wx = #slide.q pool.tmp
scoreboard players operation #slide.p pool.tmp = @s pool.fwz
function pool:physics/motion/slide/fine
scoreboard players operation @s pool.wz = #slide.q pool.tmp
