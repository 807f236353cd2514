check --format sarif --io ../../examples/weldcell.io ../../examples/weldcell.mod
