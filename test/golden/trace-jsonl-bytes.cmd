trace --format jsonl --rules store trace-bytes.mod
