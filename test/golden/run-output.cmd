run run-hello.mod
