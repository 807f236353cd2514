check --allow-unknown hints.mod
