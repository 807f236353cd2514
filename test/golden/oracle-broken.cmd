oracle --impl 'echo not json' oracle-program.mod
