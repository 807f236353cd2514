run backup-library
