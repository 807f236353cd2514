test --filter slot --jobs 2 ../../examples/pickcell
