MODULE PROC
! @expect-message 1:8: syntax error: expected the module name, an identifier, after MODULE (§9.2); found PROC
ENDMODULE
