# The process supervision of spec/motion/20-async-*.mod (the example of §7.4): the process
# fails 4.85 s after the first MoveL of my_process began (0.420566 s: the MoveJ before it).
signal do_myproc do
signal di_proc_sup di
at 5.270566 di_proc_sup 1
