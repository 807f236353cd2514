check msg-function-no-return.mod
