debug --script debug-back-moves.dbg ../../spec/06-backward/03-backward-moves.mod
