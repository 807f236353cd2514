run ../../examples/weldcell.mod
