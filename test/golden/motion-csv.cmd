motion --io motion-cell.io --statement-time 0 --csv /dev/stdout --csv-step 0.25 motion-cell.mod
