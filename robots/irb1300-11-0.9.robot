# ABB IRB 1300-11/0.9: a serial six-axis arm with a spherical wrist (doc/motion.md, "The robot library").
# Dimensions and axis ranges: as given for this arm in the robotkinematicscatalogue package (PyPI,
#   version 1.1.2, ABB_IRB_1300_11: modified DH parameters and joint limits); figures only. Axis 6
#   there is +-242, read as ABB's +-242 revolutions (doc/motion.md R-2.13-numbers2's note).
# Axis speeds: ESTIMATED (no source found: the IRB 1200-5/0.9's, a close relative; doc/rulings.md
#   R-library-estimates); axis 3 measured against the lower arm as on the IRB 1200 (ESTIMATED).
# DH reading (derived, doc/motion.md "The robot library"): as the other serial arms.
# max_tcp_speed: ESTIMATED.
name "ABB IRB 1300-11/0.9"
#     DH: a (mm)  alpha (deg)  d (mm)  offset (deg)   range (deg)   speed (deg/s)
axis 1    50   -90   544    0    -180 180      288
axis 2   425     0     0  -90    -100 130      240
axis 3    40   -90     0    0    -210  65      300
axis 4     0    90   425    0    -230 230      400
axis 5     0   -90     0    0    -130 130      405
axis 6     0     0    90  180    -87120 87120  600
max_tcp_speed 7000
# the reach of the wrist centre, mm: the product's name
reach 900
