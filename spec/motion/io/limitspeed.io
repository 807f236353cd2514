# The system input LimitSpeed of spec/motion/63-speedlim-limitspeed.mod: di_lim (EIO.cfg's
# SYSSIG_IN -Signal "di_lim" -Action "LimitSpeed" -Arg6 "ROB_1") goes to 1 at 1 s.
signal di_lim di
system-input LimitSpeed di_lim ROB_1
at 1 di_lim 1
