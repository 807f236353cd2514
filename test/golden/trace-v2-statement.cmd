trace --level statement observable-v2.mod
