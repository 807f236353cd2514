run --engine machine --json backup-multimove
