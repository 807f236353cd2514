trace --from 19 --to 46 --io controller-cell.io controller-cell.mod
