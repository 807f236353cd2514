check for-without-from.mod semantic-errors.mod
