run - < run-hello.mod
