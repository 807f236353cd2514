# ABB IRB 360-1/1130 (FlexPicker): a delta, three arms and a turning axis 4 (doc/motion.md, "The robot
# library"; structure delta, doc/rulings.md R-structure-delta).
# ESTIMATED throughout (doc/rulings.md R-library-estimates): no source of its arm dimensions, axis
#   ranges or axis speeds was found. Published: the working range, a cylinder 1130 mm across and 250
#   mm high (the product's name); the dimensions below are chosen so that the plate reaches 565 mm
#   from the centre over more than 250 mm of height (from 450 to 780 mm below the base), with the
#   arms within -60 to +110 degrees.
# Library name irb360-1-1.13 (reach in m as the others); MOC.cfg type ROB1_360_1.13_1.
structure delta
name "ABB IRB 360-1/1130"
#     a (mm)  alpha   d (mm)  offset   range (deg)   speed (deg/s)
# axes 1 to 3: a = upper arm, d = rod; axis 4: a = base radius less plate radius, d = flange below the plate
axis 1   290     0     800      0      -60  110      600
axis 2   290     0     800      0      -60  110      600
axis 3   290     0     800      0      -60  110      600
axis 4   150     0      50      0     -360  360     1440
max_tcp_speed 10000
# the reach, mm: the working range's radius
reach 565
