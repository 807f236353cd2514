motion --robot ROB1_2400_1.5_10 --statement-time 0 --svg /dev/stdout robot-library-cell.mod
