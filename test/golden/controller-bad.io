# An error on line 3: an output cannot be driven by the outside world.
signal do1 do
at 0.5 do1 1
