motion --io motion-cell.io --statement-time 0 --svg /dev/stdout motion-cell.mod
