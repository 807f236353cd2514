trace --format jsonl --from 1 --to 13 trace-late.mod
