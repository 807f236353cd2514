# The signals of the spec/08-io cases (format: doc/controller.md).
signal di1 di
signal di2 di 1
signal do1 do
signal do2 do 1
signal ai1 ai 2.5
signal ao1 ao
signal gi1 gi 5
signal go1 go
at 1 di1 1
at 2 di1 0
at 3 gi1 12
at 4 ai1 7
