check hints.mod
