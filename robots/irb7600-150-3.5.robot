# ABB IRB 7600-150/3.5: a serial six-axis arm with a spherical wrist (doc/motion.md, "The robot library").
# Dimensions, axis ranges and axis speeds: ABB's product specification of the IRB 7600-150/3.5, chapter
#   "Robot motion" (working range figure; table of axis working ranges and maximum axis speeds),
#   as transcribed in ROS-Industrial's abb_experimental repository, abb_irb7600_support/urdf/irb7600_150_350_macro.xacro
#   (joint origins, limits and velocities); figures only.
# DH reading (derived, doc/motion.md "The robot library"): axis 1 d = height of axis 2 above the
#   base, a = axis 2 ahead of axis 1; axis 2 a = lower arm; axis 3 a = axis 4 above axis 3;
#   axis 4 d = axis 3 to the wrist centre; axis 6 d = wrist centre to the flange.
# max_tcp_speed: ESTIMATED (the specification gives no figure; doc/motion.md "The robot library").
# structure coupled-axis3: axis 3 is the upper arm's attitude against the horizontal, not its angle to
#   the lower arm, as ABB's controller reports it for this arm (ROS-Industrial's driver couples joints 2
#   and 3 for it: J23_coupled true in its launch files; doc/rulings.md R-structure).
structure coupled-axis3
name "ABB IRB 7600-150/3.5"
#     DH: a (mm)  alpha (deg)  d (mm)  offset (deg)   range (deg)   speed (deg/s)
axis 1   410   -90   780    0    -180 180   100
axis 2   1075     0     0  -90    -60 85   60
axis 3   165   -90     0    0    -180 60   60
axis 4     0    90   2012    0    -300 300   100
axis 5     0   -90     0    0    -100 100   100
axis 6     0     0   250  180    -360 360   190
max_tcp_speed 5000
# the reach of the wrist centre, mm: the product specification's figure (the product's name rounds it)
reach 3500
