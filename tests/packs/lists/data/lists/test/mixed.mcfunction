scoreboard objectives add lists dummy
# DataCommands.insertAtIndex: each value is added at the next index, in order
data modify storage lists:io l set value [[1], 2]
data modify storage lists:io l prepend value "s"
data modify storage lists:io l insert 1 from storage lists:io l[1][]
assert data storage lists:io {l: ["s", 1, [1], 2]}
data modify storage lists:io l[0] set value {c: 1}
assert data storage lists:io {l: [{c: 1}, 1, [1], 2]}
execute store success score #ok lists run data modify storage lists:io l append value 3.5f
assert score #ok lists matches 1
# a typed array still takes numbers only
data modify storage lists:io a set value [I; 1, 2]
execute store success score #ok lists run data modify storage lists:io a append value "x"
assert score #ok lists matches 0
