run --json --stub-unmodelled stub-unmodelled.mod
