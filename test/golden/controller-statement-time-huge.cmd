run --statement-time=1e308 controller-date.mod
