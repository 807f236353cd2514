run run-error.mod
