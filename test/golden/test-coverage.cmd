test --filter grip --coverage /dev/null ../../examples/pickcell
