# pool:ball/rewind — back to the state saved at the sub-step's start, then advance by #step
# (the time of the event being resolved). Reads: #step pool.tmp, @s saved scores.
function pool:ball/restore
function pool:ball/advance
