run --robot ROB1_2400_1.5_12 robot-library-cell.mod
