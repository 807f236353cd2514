run --allow-unknown --json --entry second run-unknown-names.mod
