# the caller's frame goes under the stack, a new one is made from call.args
data modify storage stack: frames prepend from storage stack: this
data modify storage stack: this set value {}
data modify storage stack: this.args set from storage stack: call.args
data remove storage stack: call
