parse semantic-later.mod for-without-from.mod exponent-out-of-range.mod
