# Flattens storage lists:io value in place, depth first: a list element is spread where it stood.
data modify storage lists:io queue set from storage lists:io value
data modify storage lists:io value set value []
function lists:flatten/next
