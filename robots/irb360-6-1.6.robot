# ABB IRB 360-6/1600 (FlexPicker): a delta, three arms and a turning axis 4 (doc/motion.md, "The robot
# library"; structure delta, doc/rulings.md R-structure-delta). MOC.cfg type ROB1_360_1.6_6.
# ESTIMATED throughout (doc/rulings.md R-library-estimates, R-structure-delta): no source of its arm
#   dimensions, axis ranges or axis speeds was found. Published: the working range, 1600 mm across
#   (the product's name), payload 6 kg; the dimensions below are chosen so that the plate reaches
#   800 mm from the centre, and the targets of a real cell of this arm (a backup's, 1107 to 1197 mm
#   below the base) lie in the working range, with the arms within -60 to +110 degrees. Axis speeds
#   and max_tcp_speed as the IRB 360-1/1130's (ESTIMATED).
structure delta
name "ABB IRB 360-6/1600"
#     a (mm)  alpha   d (mm)  offset   range (deg)   speed (deg/s)
# axes 1 to 3: a = upper arm, d = rod; axis 4: a = base radius less plate radius, d = flange below the plate
axis 1   450     0    1200      0      -60  110      600
axis 2   450     0    1200      0      -60  110      600
axis 3   450     0    1200      0      -60  110      600
axis 4   150     0      50      0     -360  360     1440
max_tcp_speed 10000
# the reach, mm: the working range's radius
reach 800
