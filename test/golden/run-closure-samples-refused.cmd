run --engine closure --json --samples 10 run-hello.mod
