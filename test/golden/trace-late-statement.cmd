trace --level statement trace-late.mod
