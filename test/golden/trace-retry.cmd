trace trace-retry.mod
