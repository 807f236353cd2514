run --json backup-events
