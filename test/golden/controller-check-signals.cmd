check --io controller-cell.io controller-cell.mod
