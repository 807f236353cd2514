trace trace-late.mod
