MODULE while_statement
! @section 4.19
! @expect ok
! @description The example of section 4.19 (elision completed), and an empty body.
  VAR num a;
  VAR num b;
  PROC main()
    WHILE a < b DO
      a := a + 1;
    ENDWHILE
    WHILE <EXP> DO
    ENDWHILE
  ENDPROC
ENDMODULE
