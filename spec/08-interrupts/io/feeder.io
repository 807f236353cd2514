# The feeder of the manual's chapter 8 example (软中断程序): sig1 says the feeder is empty,
# sig3 that it is full.
signal sig1 di
signal sig3 di
at 1 sig3 1
at 2 sig3 0
at 3 sig1 1
at 4 sig1 0
at 5 sig3 1
