run --io controller-deadlock.io controller-deadlock.mod
