# ABB IRB 6660-205/1.9: a six-axis arm for pre-machining, its upper arm driven through a parallel arm
# (doc/motion.md, "The robot library"). MOC.cfg type ROB1_6660_1.90_205.
# Dimensions, axis ranges and axis speeds: ABB's product specification of the IRB 6660-205/1.9 ("Robot
#   motion"), as transcribed in ROS-Industrial's abb_experimental repository,
#   abb_irb6660_support/urdf/irb6660_205_190_macro.xacro (joint origins, limits and velocities);
#   figures only. Axis 2 at 814.5 above the base and 300 ahead of axis 1, axis 3 700 above axis 2, axis
#   4's line 280 above axis 3, the wrist centre 893 ahead of axis 3, the flange 200 beyond it.
# DH reading (derived, doc/motion.md "The robot library"). max_tcp_speed: ESTIMATED.
# structure coupled-axis3: the parallel arm keeps the upper arm's attitude when axis 2 alone moves, as
#   on the IRB 6700 and 7600 (doc/rulings.md R-structure); axis 3's range -20..120 is of that attitude.
structure coupled-axis3
name "ABB IRB 6660-205/1.9"
#     DH: a (mm)  alpha (deg)  d (mm)  offset (deg)   range (deg)   speed (deg/s)
axis 1   300   -90   814.5    0    -180 180   130
axis 2   700     0     0  -90     -42 85   130
axis 3   280   -90     0    0     -20 120   130
axis 4     0    90   893    0    -300 300   150
axis 5     0   -90     0    0    -120 120   120
axis 6     0     0   200  180    -360 360   190
max_tcp_speed 5000
# the reach of the wrist centre, mm: the product's name (1.9 m; axis 2 at 85, the upper arm in line:
#   300 + (700 + 935.9) sin 85 = 1929.7)
reach 1900
