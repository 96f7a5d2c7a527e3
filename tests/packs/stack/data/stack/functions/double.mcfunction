function stack:push
execute store result storage stack: this.return int 2 run data get storage stack: this.args.n
function stack:pop
