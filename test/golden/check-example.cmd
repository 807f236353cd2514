check --io ../../examples/weldcell.io ../../examples/weldcell.mod
