run --json --entry nosuch oracle-program.mod
