trace --level statement --format jsonl trace-loop.mod
