trace --level statement --format jsonl trace-late.mod
