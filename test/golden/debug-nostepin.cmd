debug --script debug-nostepin.dbg debug-nostepin.mod debug-nostepin-lib.mod
