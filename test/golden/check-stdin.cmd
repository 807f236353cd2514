check - < hints.mod
