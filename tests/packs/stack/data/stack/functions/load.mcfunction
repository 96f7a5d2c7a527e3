data modify storage stack: frames set value []
