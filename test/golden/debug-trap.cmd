debug --script debug-trap.dbg debug-trap.mod
