check msg-optional-name.mod
