run --max-steps 100 run-forever.mod
