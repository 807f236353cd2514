MODULE t(SYSMODULE, SHARED)
! @expect-message 1:21: syntax error: expected a module attribute after ',': SYSMODULE, NOVIEW, NOSTEPIN, VIEWONLY or READONLY (§9.2); found the identifier SHARED
ENDMODULE
