trace trace-loop.mod
