run not-modelled.mod
