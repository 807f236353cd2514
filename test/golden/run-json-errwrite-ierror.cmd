run --json --statement-time 0 debug-event-log.mod
