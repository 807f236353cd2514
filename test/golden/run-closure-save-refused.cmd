run --engine closure --save saved run-hello.mod
