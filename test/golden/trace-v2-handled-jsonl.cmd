trace --format jsonl --from 101 --to 101 observable-v2.mod
