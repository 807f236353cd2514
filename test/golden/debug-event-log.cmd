debug --script debug-event-log.dbg debug-event-log.mod
