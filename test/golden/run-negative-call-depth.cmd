run --max-call-depth -5 run-hello.mod
