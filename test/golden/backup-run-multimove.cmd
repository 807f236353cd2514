run backup-multimove
