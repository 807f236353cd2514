run --json --io controller-cell.io controller-cell.mod
