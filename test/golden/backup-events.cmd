run backup-events
