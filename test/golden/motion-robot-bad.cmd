run --robot bad.robot motion-cell.mod
