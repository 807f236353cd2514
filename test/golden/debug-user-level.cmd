debug --script debug-user-level.dbg debug-user-level.mod debug-user-level-lib.mod
