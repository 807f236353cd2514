debug --script debug-back-trap.dbg ../../spec/06-backward/01-trap-in-backward.mod
