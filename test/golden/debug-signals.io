# The signals of debug-signals.mod (doc/controller.md, "The stimulus file")
signal diSensor di
signal doLamp do
at 0.5 diSensor 1
