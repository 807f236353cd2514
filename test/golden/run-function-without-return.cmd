run run-function-without-return.mod
