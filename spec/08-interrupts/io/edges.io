# The signals of the spec/08-interrupts cases (format: doc/controller.md).
signal di1 di
signal di2 di
signal do1 do
signal gi1 gi
at 1 di1 1
at 2 di1 0
at 2.5 gi1 3
at 3 di1 1
at 3.5 gi1 9
at 4 di1 0
