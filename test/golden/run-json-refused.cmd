run --json verdict-bad.mod
