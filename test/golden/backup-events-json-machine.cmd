run --engine machine --json backup-events
