# ABB IRB 2600-12/1.65: a serial six-axis arm with a spherical wrist (doc/motion.md, "The robot library").
# Dimensions, axis ranges and axis speeds: ABB's product specification of the IRB 2600-12/1.65, chapter
#   "Robot motion" (working range figure; table of axis working ranges and maximum axis speeds),
#   as transcribed in ROS-Industrial's abb_experimental repository, abb_irb2600_support/urdf/irb2600_12_165_macro.xacro
#   (joint origins, limits and velocities); figures only.
# DH reading (derived, doc/motion.md "The robot library"): axis 1 d = height of axis 2 above the
#   base, a = axis 2 ahead of axis 1; axis 2 a = lower arm; axis 3 a = axis 4 above axis 3;
#   axis 4 d = axis 3 to the wrist centre; axis 6 d = wrist centre to the flange.
# max_tcp_speed: ESTIMATED (the specification gives no figure; doc/motion.md "The robot library").
name "ABB IRB 2600-12/1.65"
#     DH: a (mm)  alpha (deg)  d (mm)  offset (deg)   range (deg)   speed (deg/s)
axis 1   150   -90   445    0    -180 180   175
axis 2   700     0     0  -90    -95 155   175
axis 3   115   -90     0    0    -180 75   175
axis 4     0    90   795    0    -400 400   360
axis 5     0   -90     0    0    -120 120   360
axis 6     0     0   85  180    -400 400   500
max_tcp_speed 6000
# the reach of the wrist centre, mm: the product specification's figure (the product's name rounds it)
reach 1650
