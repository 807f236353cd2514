trace --level statement trace-places.mod
