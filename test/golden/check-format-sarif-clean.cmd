check --format sarif ../../examples/weldcell.mod
