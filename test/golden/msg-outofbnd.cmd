run msg-outofbnd.mod
