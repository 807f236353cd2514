# An analog input for the ISignalAI case.
signal ai1 ai
at 1 ai1 3
at 2 ai1 6
at 3 ai1 8
at 4 ai1 2
at 5 ai1 7
