MODULE t
! @expect-message 4:3: syntax error: expected a data declaration, routine declaration or ENDMODULE: type definitions come before the data declarations (§9.2); found RECORD
  VAR num n;
  RECORD r
    num a;
  ENDRECORD
ENDMODULE
