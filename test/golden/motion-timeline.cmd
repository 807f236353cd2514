motion --io motion-cell.io --statement-time 0 --timeline /dev/stdout motion-cell.mod
