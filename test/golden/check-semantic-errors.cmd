check semantic-errors.mod
