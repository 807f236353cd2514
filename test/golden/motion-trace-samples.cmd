trace --format jsonl --samples 1 --rules wait-advance --io motion-cell.io --statement-time 0 motion-cell.mod
