check --task T_ROB1=tasks-robot.mod tasks-cell.mod
