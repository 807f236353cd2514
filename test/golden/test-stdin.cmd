test - < test-static.mod
