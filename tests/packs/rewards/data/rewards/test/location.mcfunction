# @dummy ~ ~ ~
assert not score @s rewards.low matches 1..
tp @s ~ -20 ~
await score @s rewards.low matches 1
