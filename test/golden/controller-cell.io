# The stimulus of controller-cell.mod: three parts arrive, the second while interrupts are
# disabled; the emergency stop comes while the third part is clamped.
signal di_part di
signal di_stop di
signal do_clamp do
at 1.0 di_part 1
at 1.1 di_part 0
at 1.2 di_part 1
at 1.6 di_part 0
at 2.0 di_part 1
at 2.4 di_stop 1
