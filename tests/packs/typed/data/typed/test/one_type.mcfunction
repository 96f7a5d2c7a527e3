scoreboard objectives add typed dummy
# ListTag.updateType (1.21.4): the first element fixes the list's type
data modify storage typed:io l set value [[1], [2]]
execute store success score #ok typed run data modify storage typed:io l append value 3
assert score #ok typed matches 0
execute store success score #ok typed run data modify storage typed:io l append value [3]
assert score #ok typed matches 1
assert data storage typed:io {l: [[1], [2], [3]]}
