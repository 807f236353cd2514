run --json --samples 10 --max-memory 40000 samples-history.mod
