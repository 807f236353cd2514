run --max-steps -1 run-hello.mod
