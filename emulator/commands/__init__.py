"""Each command's Python implementation, one copy used by both backends (the VM's host side and the
reference interpreter). Control flow (queue, costs, forks, returns) is not here: each backend has
its own, and they are each other's oracle."""
