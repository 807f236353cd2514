run test-static.mod --entry test_types
