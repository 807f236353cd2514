oracle --impl '"$RAPID_SEM" run --json {files}' oracle-program.mod
