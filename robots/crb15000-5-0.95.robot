# ABB CRB 15000-5/0.95 (GoFa): a six-axis collaborative arm whose wrist is offset: axis 6 runs 80 mm
# beside axis 4's line (doc/motion.md, "The robot library"; axis 5 a = 80, solved numerically).
# Dimensions, axis ranges and axis speeds: ABB's product specification of the CRB 15000, as
#   transcribed in ROS-Industrial's abb_experimental repository,
#   abb_crb15000_support/urdf/crb15000_5_95_macro.xacro (joint origins, limits, velocities; the same
#   dimensions and ranges in the robotkinematicscatalogue package's ABB_CRB_15000); figures only.
# DH reading (derived, doc/motion.md "The robot library"): as the serial arms, and axis 5 a = the
#   offset of axis 6 from axis 4's line.
# max_tcp_speed: 2200 mm/s, the product's published maximum TCP speed (recalled, UNCERTAIN).
name "ABB CRB 15000-5/0.95"
#     DH: a (mm)  alpha (deg)  d (mm)  offset (deg)   range (deg)   speed (deg/s)
axis 1     0   -90   265    0   -180 180   125
axis 2   444     0     0  -90   -180 180   125
axis 3   110   -90     0    0   -225  85   140
axis 4     0    90   470    0   -180 180   200
axis 5    80   -90     0    0   -180 180   200
axis 6     0     0   101  180   -180 180   200
max_tcp_speed 2200
# the reach, mm: the product specification's figure
reach 950
