run --json chain-long-mutual.mod
