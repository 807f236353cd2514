# The signals of CadPolishCover.mod (format: doc/controller.md).
signal doPolisherOn do
