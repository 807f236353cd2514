check --format sarif hints.mod
