MODULE t
! @expect-message 3:12: syntax error: expected '{' and the dimensions, ':=' and the initial value, or ';' after the variable's name (§2.22); found ','
  VAR num a, b;
ENDMODULE
