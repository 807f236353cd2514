run msg-no-main.mod
