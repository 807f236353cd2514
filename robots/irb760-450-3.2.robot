# ABB IRB 760-450/3.18: a four-axis palletiser, axes 1, 2, 3 and 6, the flange kept level by parallel
# rods (doc/motion.md, "The robot library"; structure palletiser, doc/rulings.md R-structure).
# Library name irb760-450-3.2: the reach as the MOC.cfg robot type gives it (ROB3_760_3.2_450).
# Dimensions and axis ranges: as given for this arm in the robotkinematicscatalogue package (PyPI,
#   inversekinematics/__4DOF/__palletizing/ABB_IRB760.py: modified DH parameters and joint limits);
#   figures only. Axis 2 at 814.5 above the base and 300 ahead of axis 1, the lower arm 1280, the upper
#   arm 1350, the flange 290 ahead of and 269 below the upper arm's end. Axis 1 +-180, axis 2 -42..82,
#   axis 3 -20..120, axis 6 +-300 degrees.
# Axis speeds: ESTIMATED (recalled from ABB's product specification, not checked: 85, 85, 85 and 175
#   degrees/s; doc/rulings.md R-library-estimates). max_tcp_speed: ESTIMATED.
structure palletiser
name "ABB IRB 760-450/3.18"
#     a (mm)  alpha   d (mm)  offset   range (deg)   speed (deg/s)
axis 1   300     0     814.5    0     -180 180      85
axis 2   1280    0       0      0      -42  82      85
axis 3   1350    0       0      0      -20 120      85
axis 6   290     0     269      0     -300 300      175
max_tcp_speed 5000
# the reach, mm: the product specification's 3.18 m (the flange at axis 2 = 82, axis 3 = 0 is at 3207.5)
reach 3180
