execute on attacker if entity @s[tag=clicks.source] run return 1
return fail
