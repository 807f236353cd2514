run --json --engine closure --entry nosuch oracle-program.mod
