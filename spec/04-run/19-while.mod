MODULE while_loop
! @format 3
! @section 4.19
! @expect ok
! @description Section 4.19's example: WHILE a < b DO a := a + 1; ENDWHILE repeats while the condition holds, which is checked before every iteration.
! @output 1
! @output 2
! @output 3
! @output a=3
! @exit 0
  VAR num a;
  VAR num b := 3;
  PROC main()
    WHILE a < b DO
      a := a + 1;
      TPWrite "" \Num:=a;
    ENDWHILE
    TPWrite "a=" \Num:=a;
  ENDPROC
ENDMODULE
