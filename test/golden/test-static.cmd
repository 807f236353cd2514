test test-static.mod
