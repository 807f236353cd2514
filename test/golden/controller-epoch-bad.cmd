run --epoch 2030-13-15T12:30:00 controller-date.mod
