trace --level statement trace-loop.mod
