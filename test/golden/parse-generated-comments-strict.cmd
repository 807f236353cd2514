parse --strict generated.mod
