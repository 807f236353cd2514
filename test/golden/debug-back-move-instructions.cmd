debug --script debug-back-move-instructions.dbg ../../spec/06-backward/05-back-move-instructions.mod
