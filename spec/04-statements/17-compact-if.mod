MODULE compact_if
! @format 2
! @section 4.17
! @expect ok
! @description A compact IF with a bool condition and one simple statement.
  VAR num counter;
  PROC main()
    IF counter > 5 OR counter < 0 counter := 0;
    IF counter = 1 TPWrite "one";
  ENDPROC
ENDMODULE
