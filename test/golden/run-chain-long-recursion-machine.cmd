run --engine machine chain-long-recursion.mod
