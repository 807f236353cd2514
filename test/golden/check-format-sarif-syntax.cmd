check --format sarif double-equal.mod
