run --epoch=2023-02-29T00:00:00 controller-date.mod
