# ABB IRB 1660ID-4/1.55: a serial six-axis arm with a hollow spherical wrist (doc/motion.md, "The robot
# library"). MOC.cfg type ROB1_1660ID_1.55_4 (ROB1_1660_ID_1.55_4 alike).
# Dimensions and axis ranges: ABB's product specification of the IRB 1660ID ("Robot motion"), as
#   transcribed in the RobotComponents robot presets (GitHub RobotComponents/RobotComponents,
#   .../Definitions/Presets/IRB1660ID_X_155.cs: axis positions at the calibration position, axis
#   limits); figures only. Axis 2 at 486.5 above the base and 150 ahead of axis 1, axis 3 700 above
#   axis 2, axis 4's line 110 above axis 3, the wrist centre 678 ahead of axis 3 (at x = 828), the
#   flange 135 beyond it. Ranges +-180, -90..150, -238..79, +-175, +-120, +-400 degrees.
# Axis speeds: ESTIMATED (recalled from ABB's product specification, not checked: 180, 180, 185, 360,
#   360 and 500 degrees/s; doc/rulings.md R-library-estimates). max_tcp_speed: ESTIMATED.
# DH reading (derived, doc/motion.md "The robot library").
name "ABB IRB 1660ID-4/1.55"
#     DH: a (mm)  alpha (deg)  d (mm)  offset (deg)   range (deg)   speed (deg/s)
axis 1   150   -90   486.5    0    -180 180   180
axis 2   700     0     0  -90     -90 150   180
axis 3   110   -90     0    0    -238 79   185
axis 4     0    90   678    0    -175 175   360
axis 5     0   -90     0    0    -120 120   360
axis 6     0     0   135  180    -400 400   500
max_tcp_speed 6000
# the reach of the wrist centre, mm: the product's name (1.55 m; stretched, 150 + 700 + 686.9 = 1536.9)
reach 1550
