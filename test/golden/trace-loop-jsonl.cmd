trace --format jsonl --to 12 trace-loop.mod
