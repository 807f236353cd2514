debug --io debug-signals.io --script debug-signals.dbg debug-signals.mod
