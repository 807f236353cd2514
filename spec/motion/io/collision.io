# A collision during the second MoveJ of spec/motion/22-collision-recovery.mod.
at 2.5 collision
