check controller-cell.mod
