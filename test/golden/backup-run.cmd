run backup-cell
