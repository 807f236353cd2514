run --max-memory 100000 run-memory-budget.mod
