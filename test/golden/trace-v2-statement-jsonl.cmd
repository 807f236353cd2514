trace --format jsonl --level statement observable-v2.mod
