run --json latin1-strings.mod
