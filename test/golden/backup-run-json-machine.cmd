run --engine machine --json backup-cell
