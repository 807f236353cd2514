run --allow-unknown run-unknown-data.mod
