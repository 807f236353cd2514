# The outside world of examples/weldcell.mod (format: doc/controller.md, "The stimulus file").
signal di_part_ready di
signal di_door di
signal do_clamp do
signal do_arc do
signal do_clean do
signal do_done do
# The operator loads a part, and takes it out after each cycle for the next one; someone opens
# the safety door during the second cycle.
at 1 di_part_ready 1
at 30 di_part_ready 0
at 32 di_part_ready 1
at 40 di_door 1
at 43 di_door 0
at 60 di_part_ready 0
at 62 di_part_ready 1
at 90 di_part_ready 0
at 92 di_part_ready 1
at 120 di_part_ready 0
