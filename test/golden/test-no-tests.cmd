test --filter nothing_matches ../../examples/pickcell
