oracle --impl 'sh oracle-wrong-impl.sh {file}' oracle-program.mod
