debug --script debug-expressions.dbg debug-expressions.mod
