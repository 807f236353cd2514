# ABB IRB 6700-200/2.60: a serial six-axis arm with a spherical wrist (doc/motion.md, "The robot library").
# Dimensions, axis ranges and axis speeds: ABB's product specification of the IRB 6700-200/2.60, chapter
#   "Robot motion" (working range figure; table of axis working ranges and maximum axis speeds),
#   as transcribed in ROS-Industrial's abb_experimental repository, abb_irb6700_support/urdf/irb6700_200_260_macro.xacro
#   (joint origins, limits and velocities); figures only.
# DH reading (derived, doc/motion.md "The robot library"): axis 1 d = height of axis 2 above the
#   base, a = axis 2 ahead of axis 1; axis 2 a = lower arm; axis 3 a = axis 4 above axis 3;
#   axis 4 d = axis 3 to the wrist centre; axis 6 d = wrist centre to the flange.
# max_tcp_speed: ESTIMATED (the specification gives no figure; doc/motion.md "The robot library").
# structure coupled-axis3: axis 3 is the upper arm's attitude against the horizontal, not its angle to
#   the lower arm, as ABB's controller reports it for this arm (ROS-Industrial's driver couples joints 2
#   and 3 for it: J23_coupled true in its launch files; doc/rulings.md R-structure).
structure coupled-axis3
name "ABB IRB 6700-200/2.60"
#     DH: a (mm)  alpha (deg)  d (mm)  offset (deg)   range (deg)   speed (deg/s)
axis 1   320   -90   780    0    -170 170   110
axis 2   1125     0     0  -90    -65 85   110
axis 3   200   -90     0    0    -180 70   110
axis 4     0    90   1142.5    0    -300 300   190
axis 5     0   -90     0    0    -130 130   150
axis 6     0     0   200  180    -360 360   210
max_tcp_speed 5000
# the reach of the wrist centre, mm: the product specification's figure (the product's name rounds it)
reach 2600
