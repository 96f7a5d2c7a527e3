scoreboard objectives add lists dummy
data modify storage lists:io value set value [1, [2, 3], [[4], 5]]
function lists:flatten/deep
assert data storage lists:io {value: [1, 2, 3, 4, 5]}
data modify storage lists:io value set value ["a", [1b, {k: 2}], [[2.5d]]]
function lists:flatten/deep
assert data storage lists:io {value: ["a", 1b, {k: 2}, 2.5d]}
