# quicksort the sortable bodies by energy (ties by id): every one starts in segment 0 at base 0
data modify storage phys:flags sorting set value 1b
scoreboard players set #next phys.seg 1
execute as @e[tag=phys.sortable] run function phys:sort/prepare
function phys:sort/step
data modify storage phys:flags sorting set value 0b
