MODULE compact_if_nested
! @section 4.17
! @expect syntax-error 9:10
! @description A compact IF is a compound statement, so it cannot be the statement of another compact IF.
  VAR bool a;
  VAR bool b;
  VAR num x;
  PROC main()
    IF a IF b x := 1;
  ENDPROC
ENDMODULE
