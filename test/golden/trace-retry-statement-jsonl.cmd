trace --format jsonl --level statement trace-retry.mod
