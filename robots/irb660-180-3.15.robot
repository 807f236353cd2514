# ABB IRB 660-180/3.15: a four-axis palletiser, axes 1, 2, 3 and 6, the flange kept level by parallel
# rods (doc/motion.md, "The robot library"; structure palletiser, doc/rulings.md R-structure).
# Dimensions and axis ranges: as given for this arm in the robotkinematicscatalogue package
#   (PyPI, version 1.1.2, inversekinematics/__4DOF/__palletizing/ABB_IRB660_180.py: modified DH
#   parameters and joint limits); figures only. Axis 2 range -42 to +82, axis 3 -20 to +120, axes 1
#   and 6 +-180 and +-300 degrees.
# Axis speeds: ESTIMATED (recalled from ABB's product specification, not checked against it: 130,
#   130, 130 and 300 degrees/s; doc/rulings.md R-library-estimates). max_tcp_speed: ESTIMATED.
# Reading of the dimensions (derived): axis 2 is 300 ahead of and 800 above the base, the lower arm
#   1280, the upper arm 1350, the flange 260 ahead of and 247 below the upper arm's end.
structure palletiser
name "ABB IRB 660-180/3.15"
#     a (mm)  alpha   d (mm)  offset   range (deg)   speed (deg/s)
axis 1   300     0     800      0     -180 180      130
axis 2   1280    0       0      0      -42  82      130
axis 3   1350    0       0      0      -20 120      130
axis 6   260     0     247      0     -300 300      300
max_tcp_speed 5000
# the reach, mm: the product's name (3.15 m; the flange at axis 2 = 82, axis 3 = 0 is at 3177)
reach 3150
