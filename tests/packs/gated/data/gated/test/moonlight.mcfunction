# under the open sky at midnight the light is 15 less the sky's darkening of 11, which the level
# updates at its next tick (Level.updateSkyBrightness before ServerLevel.tickTime)
time set 18000
assert not predicate gated:moonlit
await delay 1t
assert predicate gated:moonlit
time set 6000
await delay 1t
assert not predicate gated:moonlit
