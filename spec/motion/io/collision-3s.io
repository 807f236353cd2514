# A collision at 3 s: spec/motion/23-collision-motion-pointer-gone.mod.
at 3 collision
