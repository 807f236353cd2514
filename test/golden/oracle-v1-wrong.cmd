oracle --impl 'sh oracle-v1-wrong-impl.sh {file}' observable-v2.mod
