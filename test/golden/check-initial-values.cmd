check check-initial-values.mod
