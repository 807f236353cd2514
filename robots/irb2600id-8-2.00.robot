# ABB IRB 2600ID-8/2.00: a serial six-axis arm with a hollow ("integrated dress pack") spherical wrist
# (doc/motion.md, "The robot library"). MOC.cfg type ROB1_2600ID_2.00_8.
# Dimensions and axis ranges: ABB's product specification of the IRB 2600ID-8/2.00 ("Robot motion":
#   working range figure, table of axis working ranges), as transcribed in the RobotComponents
#   robot presets (GitHub RobotComponents/RobotComponents, .../Definitions/Presets/IRB2600ID_8_200.cs:
#   axis positions at the calibration position, axis limits); figures only. Axis 2 at 445 above the
#   base and 150 ahead of axis 1, axis 3 900 above axis 2, axis 4's line 150 above axis 3, the wrist
#   centre 938 ahead of axis 3, the flange 200 beyond it. Ranges +-180, -95..155, -180..75, +-175,
#   +-120, +-400 degrees.
# Axis speeds: ESTIMATED (those of the IRB 2600, robots/irb2600-12-1.65.robot; the source gives none;
#   doc/rulings.md R-library-estimates). max_tcp_speed: ESTIMATED.
# DH reading (derived, doc/motion.md "The robot library"), as the IRB 2600's.
name "ABB IRB 2600ID-8/2.00"
#     DH: a (mm)  alpha (deg)  d (mm)  offset (deg)   range (deg)   speed (deg/s)
axis 1   150   -90   445    0    -180 180   175
axis 2   900     0     0  -90     -95 155   175
axis 3   150   -90     0    0    -180 75   175
axis 4     0    90   938    0    -175 175   360
axis 5     0   -90     0    0    -120 120   360
axis 6     0     0   200  180    -400 400   500
max_tcp_speed 6000
# the reach of the wrist centre, mm: the product's name (2.00 m; stretched, 150 + 900 + 949.9 = 1999.9)
reach 2000
