debug --script debug-backward.dbg ../../spec/06-backward/02-backward-handler.mod
