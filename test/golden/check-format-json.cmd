check --format json hints.mod
