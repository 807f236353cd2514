trace --to 12 run-error.mod
