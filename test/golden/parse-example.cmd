parse ../../examples/weldcell.mod
