run --engine machine --json msg-outofbnd.mod
