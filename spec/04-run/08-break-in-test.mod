MODULE break_in_test
! @format 3
! @section 4.8
! @section 4.20
! @expect ok
! @description A BREAK inside a TEST inside a loop ends the loop, not just the TEST (section 4.8: the smallest enclosing loop).
! @output one
! @output two
! @output after
! @exit 0
  PROC main()
    VAR num n;
    WHILE TRUE DO
      n := n + 1;
      TEST n
      CASE 1:
        TPWrite "one";
      CASE 2:
        TPWrite "two";
      DEFAULT:
        BREAK;
      ENDTEST
    ENDWHILE
    TPWrite "after";
  ENDPROC
ENDMODULE
