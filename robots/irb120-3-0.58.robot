# ABB IRB 120-3/0.58: a serial six-axis arm with a spherical wrist (doc/motion.md, "The robot library").
# Dimensions, axis ranges and axis speeds: ABB's product specification of the IRB 120-3/0.58, chapter
#   "Robot motion" (working range figure; table of axis working ranges and maximum axis speeds),
#   as transcribed in ROS-Industrial's abb_experimental repository, abb_irb120_support/urdf/irb120_3_58_macro.xacro
#   (joint origins, limits and velocities); figures only.
# DH reading (derived, doc/motion.md "The robot library"): axis 1 d = height of axis 2 above the
#   base, a = axis 2 ahead of axis 1; axis 2 a = lower arm; axis 3 a = axis 4 above axis 3;
#   axis 4 d = axis 3 to the wrist centre; axis 6 d = wrist centre to the flange.
# max_tcp_speed: 6.2 m/s, as the built-in IRB 120 (installed-facts.md §3, UNCERTAIN).
name "ABB IRB 120-3/0.58"
#     DH: a (mm)  alpha (deg)  d (mm)  offset (deg)   range (deg)   speed (deg/s)
axis 1   0   -90   290    0    -165 165   250
axis 2   270     0     0  -90    -110 110   250
axis 3   70   -90     0    0    -110 70   250
axis 4     0    90   302    0    -160 160   320
axis 5     0   -90     0    0    -120 120   320
axis 6     0     0   72  180    -400 400   420
max_tcp_speed 6200
# the reach of the wrist centre, mm: the product specification's figure (the product's name rounds it)
reach 580
