debug --statement-time 0 --script debug-back-moveto.dbg ../../spec/06-backward/04-backward-moveto.mod
