run --stub-unmodelled stub-unmodelled.mod
