debug --script backup-events-debug.script backup-events
