# The process supervision of spec/motion/33 and 34 (section 7.4, the error after my_process
# ended): the process fails 9.85 s after the clock started (0.420566 s: the MoveJ before it),
# while the robot is still on the first call's last MoveL and the program pointer in the second
# call.
signal do_myproc do
signal di_proc_sup di
at 10.270566 di_proc_sup 1
