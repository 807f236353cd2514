run --json run-error.mod
