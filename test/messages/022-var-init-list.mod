MODULE t
! @expect-message 3:17: syntax error: expected ';' to end the variable declaration (§2.22); found ','
  VAR num a := 1, 2;
ENDMODULE
