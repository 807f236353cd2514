# The same signals with no part ever arriving: the sensor stays at 0.
signal doGripper do
signal diPartGripped di
