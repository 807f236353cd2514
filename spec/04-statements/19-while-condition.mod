MODULE while_condition
! @format 2
! @section 4.19
! @section 3.4
! @expect ok
! @description Section 4.19's example: WHILE a < b.
  VAR num a;
  VAR num b := 10;
  PROC main()
    WHILE a < b DO
      a := a + 1;
    ENDWHILE
  ENDPROC
ENDMODULE
