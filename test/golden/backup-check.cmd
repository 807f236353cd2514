check backup-cell
