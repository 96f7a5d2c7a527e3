item modify block ~ ~ ~ container.0 craft:consume_one
item modify block ~ ~ ~ container.1 craft:consume_one
item modify block ~ ~ ~ container.2 craft:consume_one
loot insert ~ ~ ~ loot craft:sword
