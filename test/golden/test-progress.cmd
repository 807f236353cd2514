test --progress --filter slot ../../examples/pickcell
