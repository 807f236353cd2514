test --engine closure --cobertura /dev/null test-static.mod
