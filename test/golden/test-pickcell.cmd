test ../../examples/pickcell
