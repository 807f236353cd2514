check msg-undeclared-signal.mod
