test test-bad-directive.mod
