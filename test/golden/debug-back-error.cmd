debug --script debug-back-error.dbg ../../spec/06-backward/03-error-in-backward.mod
