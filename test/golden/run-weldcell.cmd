run --io ../../examples/weldcell.io ../../examples/weldcell.mod
