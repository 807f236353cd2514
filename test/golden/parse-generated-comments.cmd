parse --print generated.mod
