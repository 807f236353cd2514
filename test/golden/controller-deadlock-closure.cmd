run --engine closure --io controller-deadlock.io controller-deadlock.mod
