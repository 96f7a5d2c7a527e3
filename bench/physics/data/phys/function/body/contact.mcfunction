# as and at a body with neighbours: each neighbour counts a hit and takes a share of the energy
data modify storage phys:flags contact set value 1b
execute positioned ~-3 ~-2 ~-3 as @e[dx=6,dy=4,dz=6,tag=phys.body,tag=!phys.self] run scoreboard players add @s phys.hits 1
scoreboard players operation #share phys.tmp = @s phys.energy
scoreboard players operation #share phys.tmp /= #8 phys.const
scoreboard players operation @s phys.energy -= #share phys.tmp
scoreboard players operation @e[tag=phys.body,tag=!phys.self,tag=!phys.sleep,distance=..2,limit=1,sort=nearest] phys.energy += #share phys.tmp
execute if entity @s[tag=phys.heavy] run scoreboard players operation @e[tag=phys.light,distance=..3] phys.energy += #2 phys.const
