run stub-unmodelled.mod
