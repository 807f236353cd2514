oracle --impl 'sh oracle-partial-impl.sh {file}' oracle-program.mod
