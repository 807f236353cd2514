run --max-memory 1000000 run-memory-budget.mod
