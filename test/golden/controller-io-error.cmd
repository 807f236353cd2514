run --io controller-bad.io run-hello.mod
