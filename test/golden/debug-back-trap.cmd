debug --script debug-back-trap.dbg debug-back-trap.mod
