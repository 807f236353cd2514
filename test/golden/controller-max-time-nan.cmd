run --max-time=nan controller-date.mod
