# what the module leaves behind goes, then the module turns itself off
scoreboard players reset #ticks lib.data
datapack disable "file/uninstall_lib"
scoreboard players set #uninstalled lib.data 1
