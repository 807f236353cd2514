MODULE t;
! @expect-message 1:9: syntax error: expected a module attribute list in parentheses, a declaration, or ENDMODULE after the module name (§9.2); found ';'
ENDMODULE
