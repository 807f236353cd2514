debug --script debug-steps.dbg debug-steps.mod
