trace --retry-limit -1 run-hello.mod
