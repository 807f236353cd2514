# ABB IRB 7600-400/2.55: a serial six-axis arm with a spherical wrist (doc/motion.md, "The robot
# library"). MOC.cfg type ROB1_7600_2.55_400.
# Dimensions and axis ranges: ABB's product specification of the IRB 7600-400/2.55 ("Robot motion"), as
#   transcribed in the RobotComponents robot presets (GitHub RobotComponents/RobotComponents,
#   .../Definitions/Presets/IRB7600_400_255.cs: axis positions at the calibration position, axis
#   limits); figures only. Axis 2 at 780 above the base and 410 ahead of axis 1, axis 3 1075 above
#   axis 2, axis 4's line 165 above axis 3, the wrist centre 1056 ahead of axis 3, the flange 250
#   beyond it. Ranges +-180, -60..85, -180..60, +-300, +-100, +-360 degrees.
# Axis speeds: ESTIMATED (recalled from ABB's product specification, not checked: 75, 50, 55, 70, 60
#   and 120 degrees/s; doc/rulings.md R-library-estimates). max_tcp_speed: ESTIMATED.
# structure coupled-axis3: as the IRB 7600-150/3.5 (doc/rulings.md R-structure).
structure coupled-axis3
name "ABB IRB 7600-400/2.55"
#     DH: a (mm)  alpha (deg)  d (mm)  offset (deg)   range (deg)   speed (deg/s)
axis 1   410   -90   780    0    -180 180   75
axis 2   1075     0     0  -90    -60 85   50
axis 3   165   -90     0    0    -180 60   55
axis 4     0    90   1056    0    -300 300   70
axis 5     0   -90     0    0    -100 100   60
axis 6     0     0   250  180    -360 360   120
max_tcp_speed 5000
# the reach of the wrist centre, mm: the product's name (2.55 m; stretched level, 410 + 1075 + 1068.8 = 2553.8)
reach 2550
