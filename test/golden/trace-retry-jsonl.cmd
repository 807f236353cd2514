trace --format jsonl trace-retry.mod
