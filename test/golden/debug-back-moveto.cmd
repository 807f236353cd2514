debug --script debug-back-moveto.dbg --statement-time 0 ../../spec/06-backward/04-backward-moveto.mod
