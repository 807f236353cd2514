trace --level statement --statement-time 0 debug-event-log.mod
