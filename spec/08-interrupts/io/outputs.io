# An analog and a group output for the ISignalAO and ISignalGO case: the program drives them.
signal ao1 ao
signal go1 go 2
