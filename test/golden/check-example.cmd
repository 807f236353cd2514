check ../../examples/weldcell.mod
