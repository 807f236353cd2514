debug --script debug-back-refused.dbg ../../spec/06-backward/01-restrictions.mod
