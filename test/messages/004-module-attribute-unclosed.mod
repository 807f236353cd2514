MODULE t(SYSMODULE
! @expect-message 2:1: syntax error: expected ',' or ')' after the module attribute (§9.2); found a comment
ENDMODULE
