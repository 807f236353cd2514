parse exponent-out-of-range.mod
