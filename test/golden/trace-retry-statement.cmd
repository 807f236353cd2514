trace --level statement trace-retry.mod
