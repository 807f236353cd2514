oracle --impl 'sh oracle-store-impl.sh {file}' observable-v2.mod
