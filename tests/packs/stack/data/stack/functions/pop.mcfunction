data modify storage stack: call.return set from storage stack: this.return
data modify storage stack: this set from storage stack: frames[0]
data remove storage stack: frames[0]
