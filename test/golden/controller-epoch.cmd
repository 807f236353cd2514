run --epoch 2030-06-15T12:30:00 --statement-time 0 --max-time 86400 controller-date.mod
