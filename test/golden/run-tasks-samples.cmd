run --json --samples 2 --task T_B=tasks-cell-wait.mod --task T_ROB1=tasks-move.mod --motion-task T_ROB1
