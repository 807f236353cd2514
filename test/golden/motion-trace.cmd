trace --rules wait --io motion-cell.io --statement-time 0 motion-cell.mod
