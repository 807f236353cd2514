check --format json double-equal.mod
