execute unless data storage lists:io queue[0] run return 1
data modify storage lists:io current set from storage lists:io queue[0]
data remove storage lists:io queue[0]
# a list takes one more element whatever it holds; a number, string or compound takes none
data modify storage lists:io probe set from storage lists:io current
execute store success score #list lists run data modify storage lists:io probe append value 1
execute if score #list lists matches 1 run data modify storage lists:io queue prepend from storage lists:io current[]
execute if score #list lists matches 0 run data modify storage lists:io value append from storage lists:io current
function lists:flatten/next
