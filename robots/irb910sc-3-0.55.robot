# ABB IRB 910SC-3/0.55: a four-axis SCARA, axes 1 to 4 (doc/motion.md, "The robot library"; structure
# scara, doc/rulings.md R-structure-scara). MOC.cfg type ROB1_910SC_0.55_3.
# Reach 550 mm and payload 3 kg: the product's name. The arms: ESTIMATED. The outer arm 250 and the
#   inner arm 400 of the 0.65 m variant are the figures of the IRB 910SC in the Screw Theory Toolbox
#   for Robotics exercises (ST24R, Pardos-Gotor: l1 = 0.4, l2 = 0.25 m) and of its kinematic tests in
#   roboticslab-uc3m's kinematics-dynamics (makeAbbIrb910scKinematicsFromDH); the 0.55 m variant is
#   taken to share the outer arm, so its inner arm is 550 - 250 = 300 (doc/rulings.md
#   R-library-estimates). The flange's height at axis 3 = 0: ESTIMATED.
# Axis ranges and speeds: ESTIMATED (recalled from ABB's data sheet, not checked: axis 1 +-140 and
#   axis 2 +-150 degrees, axis 3 a stroke of 180 mm, here -180..0 with 0 at the top, axis 4 +-400
#   degrees; 420 and 720 degrees/s, 1100 mm/s, 2400 degrees/s). max_tcp_speed: ESTIMATED.
structure scara
name "ABB IRB 910SC-3/0.55"
#     a (mm)  alpha   d (mm)  offset   range (deg; axis 3 mm)   speed (deg/s; axis 3 mm/s)
axis 1   300     0     200      0     -140 140      420
axis 2   250     0       0      0     -150 150      720
axis 3     0     0       0      0     -180   0     1100
axis 4     0     0       0      0     -400 400     2400
max_tcp_speed 6000
# the reach, mm: the product's name (the two arms in line)
reach 550
