trace --format jsonl --from 1 --to 3 run-error.mod
