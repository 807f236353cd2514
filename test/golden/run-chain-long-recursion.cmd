run chain-long-recursion.mod
