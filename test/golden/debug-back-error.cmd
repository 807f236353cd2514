debug --script debug-back-error.dbg ../../spec/06-backward/01-error-in-backward.mod
