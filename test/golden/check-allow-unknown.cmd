check --allow-unknown unknown-names.mod
