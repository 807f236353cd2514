run --max-time 2 --task T_ROB1=tasks-stop-early.mod --task T_B=tasks-wait-on.mod
