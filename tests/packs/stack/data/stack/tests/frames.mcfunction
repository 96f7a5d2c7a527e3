data modify storage stack: this set value {name: "caller"}
data modify storage stack: call.args.n set value 21
function stack:double
assert data storage stack: {call: {return: 42}, this: {name: "caller"}, frames: []}
# another storage of the same namespace is another storage
assert not data storage stack:other call
