run --json --task T_ROB1=tasks-robot.mod --task T_B=tasks-cell-late.mod
