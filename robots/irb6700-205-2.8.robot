# ABB IRB 6700-205/2.80: a serial six-axis arm with a spherical wrist (doc/motion.md, "The robot
# library"). MOC.cfg type ROB1_6700_2.80_205.
# Dimensions and axis ranges: ABB's product specification of the IRB 6700-205/2.80 ("Robot motion"), as
#   transcribed in the RobotComponents robot presets (GitHub RobotComponents/RobotComponents,
#   .../Definitions/Presets/IRB6700_205_280.cs: axis positions at the calibration position, axis
#   limits); figures only. Axis 2 at 780 above the base and 320 ahead of axis 1, axis 3 1280 above
#   axis 2, axis 4's line 200 above axis 3, the wrist centre 1182.5 ahead of axis 3, the flange 200
#   beyond it. Ranges +-170, -65..85, -180..70, +-300, +-130, +-360 degrees.
# Axis speeds: ESTIMATED (those of the IRB 6700-200/2.60, robots/irb6700-200-2.6.robot; the source
#   gives none; doc/rulings.md R-library-estimates). max_tcp_speed: ESTIMATED.
# structure coupled-axis3: as the other IRB 6700 (doc/rulings.md R-structure).
structure coupled-axis3
name "ABB IRB 6700-205/2.80"
#     DH: a (mm)  alpha (deg)  d (mm)  offset (deg)   range (deg)   speed (deg/s)
axis 1   320   -90   780    0    -170 170   110
axis 2   1280     0     0  -90    -65 85   110
axis 3   200   -90     0    0    -180 70   110
axis 4     0    90   1182.5    0    -300 300   190
axis 5     0   -90     0    0    -130 130   150
axis 6     0     0   200  180    -360 360   210
max_tcp_speed 5000
# the reach of the wrist centre, mm: the product's name (2.80 m; stretched level, 320 + 1280 + 1199.3 = 2799.3)
reach 2800
