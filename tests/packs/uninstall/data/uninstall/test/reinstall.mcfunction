# A module uninstalled by its own function stops ticking, and every load function runs again on the
# next tick; enabled again, it installs and ticks again.
scoreboard players set #loads probe 0
assert score #loads lib.data matches 1
function lib:uninstall
assert score #uninstalled lib.data matches 1
execute store result score #enabled probe run datapack list enabled
assert score #enabled probe matches 2
execute store success score #again probe run datapack disable "file/uninstall_lib"
assert score #again probe matches 0
await delay 3t
assert score #loads probe matches 1
assert score #loads lib.data matches 1
assert not score #ticks lib.data matches 1..
execute store result score #enabled probe run datapack enable "file/uninstall_lib"
assert score #enabled probe matches 3
await delay 1t
assert score #loads probe matches 2
assert score #loads lib.data matches 2
assert score #ticks lib.data matches 1..
