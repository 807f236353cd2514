# ABB IRB 1200-5/0.9: a serial six-axis arm with a spherical wrist (doc/motion.md, "The robot library").
# Dimensions, axis ranges and axis speeds: ABB's product specification of the IRB 1200-5/0.9, chapter
#   "Robot motion" (working range figure; table of axis working ranges and maximum axis speeds),
#   as transcribed in ROS-Industrial's abb_experimental repository, abb_irb1200_support/urdf/irb1200_5_90_macro.xacro
#   (joint origins, limits and velocities); figures only.
# DH reading (derived, doc/motion.md "The robot library"): axis 1 d = height of axis 2 above the
#   base, a = axis 2 ahead of axis 1; axis 2 a = lower arm; axis 3 a = axis 4 above axis 3;
#   axis 4 d = axis 3 to the wrist centre; axis 6 d = wrist centre to the flange.
# max_tcp_speed: ESTIMATED (the specification gives no figure; doc/motion.md "The robot library").
name "ABB IRB 1200-5/0.9"
#     DH: a (mm)  alpha (deg)  d (mm)  offset (deg)   range (deg)   speed (deg/s)
axis 1   0   -90   399.1    0    -170 170   288
axis 2   448     0     0  -90    -100 130   240
axis 3   42   -90     0    0    -200 70   300
axis 4     0    90   451    0    -270 270   400
axis 5     0   -90     0    0    -130 130   405
axis 6     0     0   82  180    -360 360   600
max_tcp_speed 7000
# the reach of the wrist centre, mm: the product specification's figure (the product's name rounds it)
reach 901
