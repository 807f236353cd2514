# The sensor of spec/motion/27-searchl.mod: it sees the part 2 s after the search begins (the
# MoveJ before it ends at 0.420566 s).
signal di_part di
at 2.420566 di_part 1
