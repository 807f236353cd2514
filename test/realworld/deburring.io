# The signals of CadDeburrFrame.mod (format: doc/controller.md); the spindle reaches its speed
# at once.
signal doSpindleOn do
signal goSpindleRpm go
signal diSpindleAtSpeed di 1
