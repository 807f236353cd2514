trace --to 3 - < run-hello.mod
