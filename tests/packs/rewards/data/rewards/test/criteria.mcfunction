# @dummy ~ ~ ~
advancement grant @s only rewards:two first
assert entity @s[advancements={rewards:two={first=true,second=false}}]
assert not entity @s[advancements={rewards:two=true}]
advancement grant @s only rewards:two second
assert entity @s[advancements={rewards:two=true}]
