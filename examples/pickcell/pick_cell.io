# The cell's signals, and a part at the pick position: the gripper's sensor says it holds the
# part from 0.5 s on (format: doc/controller.md, "The stimulus file").
signal doGripper do
signal diPartGripped di
at 0.5 diPartGripped 1
