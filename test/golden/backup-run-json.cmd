run --json backup-cell
