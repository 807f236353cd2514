trace --stub-unmodelled --rules call stub-unmodelled.mod
