run --json --engine closure observable-v2.mod
