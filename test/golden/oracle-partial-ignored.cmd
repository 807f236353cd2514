oracle --impl 'sh oracle-partial-impl.sh {file}' --ignore routine-entered --ignore routine-left oracle-program.mod
