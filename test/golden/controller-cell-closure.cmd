run --engine closure --io controller-cell.io controller-cell.mod
