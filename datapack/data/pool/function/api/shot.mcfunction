# pool:api/shot — play a shot with the cue ball (public API, a macro):
#   function pool:api/shot {angle:A, speed:S, tip_x:X, tip_y:Y, elevation:E}
# angle: cue direction in centidegrees, counter-clockwise from the table's +x (east) towards +z
# (south); speed: cue speed in mm/s, 1..6500; tip_x (right), tip_y (up): tip offset from the ball's
# centre in per mille of the radius, with tip_x^2 + tip_y^2 <= 500^2 (the miscue limit);
# elevation: cue butt raised, centidegrees 0..8900. All integers. A shot out of range, or while
# balls move, is refused with a message and changes nothing.
# Reads: the macro arguments. Writes: #api.* pool.tmp; through pool:api/shot/apply.
$scoreboard players set #api.angle pool.tmp $(angle)
$scoreboard players set #api.speed pool.tmp $(speed)
$scoreboard players set #api.tip_x pool.tmp $(tip_x)
$scoreboard players set #api.tip_y pool.tmp $(tip_y)
$scoreboard players set #api.elevation pool.tmp $(elevation)
return run function pool:api/shot/apply
