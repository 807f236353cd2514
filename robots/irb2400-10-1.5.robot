# ABB IRB 2400-10/1.5: a serial six-axis arm with a spherical wrist (doc/motion.md, "The robot library").
# Dimensions, axis ranges and axis speeds: ABB's product specification of the IRB 2400-10/1.5, chapter
#   "Robot motion" (working range figure; table of axis working ranges and maximum axis speeds),
#   as transcribed in ROS-Industrial's abb repository, abb_irb2400_support/urdf/irb2400_macro.xacro
#   (joint origins, limits and velocities); figures only.
# DH reading (derived, doc/motion.md "The robot library"): axis 1 d = height of axis 2 above the
#   base, a = axis 2 ahead of axis 1; axis 2 a = lower arm; axis 3 a = axis 4 above axis 3;
#   axis 4 d = axis 3 to the wrist centre; axis 6 d = wrist centre to the flange.
# max_tcp_speed: ESTIMATED (the specification gives no figure; doc/motion.md "The robot library").
# structure coupled-axis3: axis 3 is the upper arm's attitude against the horizontal, not its angle to
#   the lower arm, as ABB's controller reports it for this arm (ROS-Industrial's driver couples joints 2
#   and 3 for it: J23_coupled true in its launch files; doc/rulings.md R-structure).
structure coupled-axis3
name "ABB IRB 2400-10/1.5"
#     DH: a (mm)  alpha (deg)  d (mm)  offset (deg)   range (deg)   speed (deg/s)
axis 1   100   -90   615    0    -180 180   150
axis 2   705     0     0  -90    -100 110   150
axis 3   135   -90     0    0    -60 65   150
axis 4     0    90   755    0    -200 200   360
axis 5     0   -90     0    0    -120 120   360
axis 6     0     0   85  180    -400 400   450
max_tcp_speed 6000
# the reach of the wrist centre, mm: the product specification's figure (the product's name rounds it)
reach 1550
