verdict oracle-program.mod
