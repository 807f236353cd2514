# large-arm.robot on a track along the world's x axis (illustrative figures): the polishing cell's
# robot, whose targets give the track's position in eax_a (950 to 2000 mm).
name "large arm on a track"
axis 1  175  -90  495    0   -180 180  175
axis 2  1095   0    0  -90    -90 150  175
axis 3  175  -90    0    0   -180  75  175
axis 4    0   90 1270    0   -400 400  250
axis 5    0  -90    0    0   -125 120  250
axis 6    0    0  135  180   -400 400  360
max_tcp_speed 7000
external eax_a linear 0 4000 1000 track 1 0 0
