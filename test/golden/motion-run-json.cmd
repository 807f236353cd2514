run --json --samples 1 --io motion-cell.io --statement-time 0 motion-cell.mod
