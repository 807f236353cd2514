debug --script debug-propagate.dbg observable-v2.mod
