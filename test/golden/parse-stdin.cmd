parse - < double-equal.mod
