run latin1-strings.mod
