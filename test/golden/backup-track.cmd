run backup-track
