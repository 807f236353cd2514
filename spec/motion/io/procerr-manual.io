# The process supervision of spec/motion/44-manual-7-4-example.mod: the process fails 1.2 s
# after the clock started (0.420566 s: the MoveJ before it), while the robot moves to p2 in the
# first call of my_process and the program pointer waits in that MoveL.
signal do_myproc do
signal di_proc_sup di
at 1.620566 di_proc_sup 1
