run --engine machine run-raise-system-error-in-handler.mod
