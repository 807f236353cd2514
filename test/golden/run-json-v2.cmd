run --json observable-v2.mod
