run run-raise-system-error-in-handler.mod
