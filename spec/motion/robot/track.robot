# spec/motion cases of external axes: the IRB 120 on a track along x (eax_a), and a rotating
# positioner axis (eax_b). The format: doc/motion.md, "The robot description".
name "IRB 120 on a track, one positioner axis"
#     DH: a (mm)  alpha (deg)  d (mm)  offset (deg)   range (deg)   speed (deg/s)
axis 1      0        -90        290       0          -165   165      250
axis 2      270        0          0     -90          -110   110      250
axis 3      70       -90          0       0          -110    70      250
axis 4      0         90        302       0          -160   160      320
axis 5      0        -90          0       0          -120   120      320
axis 6      0          0         72     180          -400   400      420
max_tcp_speed 6200
# external NAME linear|rotating MIN MAX SPEED [track DX DY DZ]
#   mm or degrees; mm/s or degrees/s; track: the robot's base moves along DX DY DZ (world)
external eax_a linear   0 2000 1000 track 1 0 0
external eax_b rotating -180 180 90
