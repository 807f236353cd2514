run --json --statement-time 0 motion-end.mod
