MODULE placeholder_cse
! @section 2.9
! @section 4.20
! @expect ok
! @description <CSE> stands for a CASE clause.
  VAR num x;
  PROC main()
    TEST x
    CASE 1:
      x := 2;
    <CSE>
    DEFAULT:
      x := 0;
    ENDTEST
  ENDPROC
ENDMODULE
