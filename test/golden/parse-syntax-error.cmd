parse for-without-from.mod
