parse no-such-file.mod
