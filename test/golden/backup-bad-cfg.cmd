run backup-bad-cfg
