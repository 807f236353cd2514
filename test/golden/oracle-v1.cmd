oracle --impl 'sh oracle-v1-impl.sh {file}' observable-v2.mod oracle-program.mod
