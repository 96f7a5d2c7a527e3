# the usual player-tick hook: count, then revoke so it fires again next tick
scoreboard players add @s rewards.ticks 1
advancement revoke @s only rewards:tick_hook
