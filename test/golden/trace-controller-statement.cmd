trace --level statement --io controller-cell.io controller-cell.mod
