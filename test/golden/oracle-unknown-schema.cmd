oracle --impl 'sh oracle-schema3-impl.sh {file}' oracle-program.mod
